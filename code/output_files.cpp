// The outputs of code/output_files.h: what a path is (classifyOutput, sameFile), temporaries
// beside their targets, the signal handlers that remove them, and the locked commit.
#include "output_files.h"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <climits>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <dirent.h>
#include <fcntl.h>
#include <memory>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>
#include <utility>

namespace dt {

namespace {

std::string sysReason() { return std::strerror(errno); }

std::string dirOf(const std::string& path) {
  const std::size_t slash = path.rfind('/');
  return slash == std::string::npos ? "." : (slash == 0 ? "/" : path.substr(0, slash));
}

std::string baseOf(const std::string& path) {
  const std::size_t slash = path.rfind('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

std::string canonicalNew(const std::string& path) {
  char buf[PATH_MAX];
  if (::realpath(dirOf(path).c_str(), buf) == nullptr) return path;
  return std::string(buf) + "/" + baseOf(path);
}

// The descriptor a path names without a file of its own: "-" and /dev/stdout are 1,
// /dev/stderr 2, /dev/stdin 0, /dev/fd/N and /proc/self/fd/N are N; -1 for any other path.
// Writing to the descriptor keeps the shell's offset and mode (a `>>` redirection appends).
int inheritedFd(const std::string& path) {
  if (path == "-" || path == "/dev/stdout") return 1;
  if (path == "/dev/stderr") return 2;
  if (path == "/dev/stdin") return 0;
  for (const std::string prefix : {"/dev/fd/", "/proc/self/fd/"}) {
    if (path.compare(0, prefix.size(), prefix) != 0 || path.size() == prefix.size()) continue;
    const std::string n = path.substr(prefix.size());
    if (n.size() > 6 || n.find_first_not_of("0123456789") != std::string::npos) continue;
    return std::atoi(n.c_str());
  }
  return -1;
}

const char* kindName(mode_t m) {
  if (S_ISREG(m)) return "a regular file";
  if (S_ISDIR(m)) return "a directory";
  if (S_ISCHR(m)) return "a character device";
  if (S_ISBLK(m)) return "a block device";
  if (S_ISFIFO(m)) return "a named pipe";
  if (S_ISSOCK(m)) return "a socket";
  return "a special file";
}

// Follows `path` through symlinks to the name it finally stands for (which may not exist: a
// dangling link). `viaProc`: a link led into /proc, whose fd entries are not names that can
// be replaced (their targets read like "pipe:[1234]"); the following stops there.
std::string followLinks(const std::string& path, bool& viaProc) {
  std::string p = path;
  viaProc = false;
  for (int hops = 0; hops < 40; ++hops) {
    struct stat st;
    if (::lstat(p.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return p;
    std::vector<char> buf(PATH_MAX + 1);
    const ssize_t n = ::readlink(p.c_str(), buf.data(), buf.size());
    if (n < 0 || std::size_t(n) >= buf.size())
      throw std::runtime_error(path + ": cannot follow the symlink " + p + ": " +
                               (n < 0 ? sysReason() : std::strerror(ENAMETOOLONG)));
    const std::string t(buf.data(), std::size_t(n));
    const std::string next = !t.empty() && t[0] == '/' ? t : dirOf(p) + "/" + t;
    if (next.compare(0, 6, "/proc/") == 0) {
      viaProc = true;
      return path;
    }
    p = next;
  }
  throw std::runtime_error(path + ": cannot follow the symlink: " + std::strerror(ELOOP));
}

[[noreturn]] void refuse(const std::string& path, const std::string& file, mode_t m) {
  throw OutputRefused(path + ": is " + kindName(m) +
                      (file != path ? " (the symlink points to " + file + ")" : "") +
                      "; an output must be a regular file, a named pipe or a character device");
}

// ---- signals --------------------------------------------------------------------------------

// The temporary files of every OutputFiles, where a signal handler can read them: fixed
// arrays, a name written completely before its slot is marked used.
constexpr int kSlots = 64;
constexpr std::size_t kNameMax = 4096;
char g_tempName[kSlots][kNameMax];
volatile std::sig_atomic_t g_tempUsed[kSlots];
bool g_handlersInstalled = false;
bool g_sigpipeIgnored = false;
void (*g_commitHook)(std::size_t) = nullptr;
constexpr int kCleanupSignals[] = {SIGINT, SIGTERM, SIGHUP};

extern "C" void removeTemporariesAndDie(int sig) {
  for (int i = 0; i < kSlots; ++i)
    if (g_tempUsed[i]) ::unlink(g_tempName[i]);  // async-signal-safe
  // SA_RESETHAND restored the default action: the signal, raised again, ends the process once
  // this handler returns, with the status the caller expects from it.
  ::raise(sig);
}

// Ignores `sig` if it has its default action (a caller's own handler or SIG_IGN is kept).
void ignoreIfDefault(int sig) {
  struct sigaction old;
  if (::sigaction(sig, nullptr, &old) != 0 || old.sa_handler != SIG_DFL) return;
  struct sigaction sa;
  std::memset(&sa, 0, sizeof sa);
  sa.sa_handler = SIG_IGN;
  sigemptyset(&sa.sa_mask);
  ::sigaction(sig, &sa, nullptr);
}

void installHandlers() {
  if (g_handlersInstalled) return;
  g_handlersInstalled = true;
  for (int sig : kCleanupSignals) {
    struct sigaction old;
    if (::sigaction(sig, nullptr, &old) == 0 && old.sa_handler == SIG_IGN) continue;  // nohup
    struct sigaction sa;
    std::memset(&sa, 0, sizeof sa);
    sa.sa_handler = removeTemporariesAndDie;
    sa.sa_flags = SA_RESETHAND;
    sigemptyset(&sa.sa_mask);
    ::sigaction(sig, &sa, nullptr);
  }
  // Over `ulimit -f`, the kernel's default is to kill silently and leave the temporaries; with
  // SIGXFSZ ignored the write fails with EFBIG, which is reported and cleaned up like ENOSPC.
  ignoreIfDefault(SIGXFSZ);
}

int registerTemporary(const std::string& name) {
  installHandlers();
  if (name.size() >= kNameMax) return -1;  // not cleaned on a signal, still on every error
  for (int i = 0; i < kSlots; ++i)
    if (!g_tempUsed[i]) {
      std::memcpy(g_tempName[i], name.c_str(), name.size() + 1);
      std::atomic_signal_fence(std::memory_order_seq_cst);
      g_tempUsed[i] = 1;
      return i;
    }
  return -1;
}

void unregisterTemporary(int slot) {
  if (slot >= 0) g_tempUsed[slot] = 0;
}

// Blocks the cleanup signals for the renames. On leaving, either restores the mask, dropping
// the signals that came meanwhile (the commit is final: they must not end the process once its
// outputs are in place), or (keep) leaves them blocked for the rest of the process.
class SignalsBlocked {
 public:
  SignalsBlocked() {
    sigemptyset(&set_);
    for (int sig : kCleanupSignals) sigaddset(&set_, sig);
    ::sigprocmask(SIG_BLOCK, &set_, &old_);
  }
  void keep() { keep_ = true; }
  void dropPending() { drop_ = true; }
  ~SignalsBlocked() {
    if (keep_) return;
    sigset_t pending;
    if (drop_ && ::sigpending(&pending) == 0)
      for (int sig : kCleanupSignals) {
        if (!sigismember(&pending, sig) || sigismember(&old_, sig)) continue;
        // Setting SIG_IGN discards a pending signal (POSIX); then the handler comes back.
        struct sigaction ign, prev;
        std::memset(&ign, 0, sizeof ign);
        ign.sa_handler = SIG_IGN;
        sigemptyset(&ign.sa_mask);
        ::sigaction(sig, &ign, &prev);
        ::sigaction(sig, &prev, nullptr);
      }
    ::sigprocmask(SIG_SETMASK, &old_, nullptr);
  }

 private:
  sigset_t set_, old_;
  bool keep_ = false, drop_ = false;
};

// flock() on the directories of the targets, in (device, inode) order so that two processes
// locking overlapping sets cannot deadlock; released when destroyed. A directory that cannot be
// opened for reading is not locked (the renames still happen, unordered with other runs).
class DirectoryLocks {
 public:
  explicit DirectoryLocks(const std::vector<std::string>& targets) {
    std::vector<std::pair<std::pair<dev_t, ino_t>, int>> dirs;
    for (const std::string& t : targets) {
      const int fd = ::open(dirOf(t).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
      struct stat st;
      if (fd < 0) continue;
      if (::fstat(fd, &st) != 0) {
        ::close(fd);
        continue;
      }
      const std::pair<dev_t, ino_t> id(st.st_dev, st.st_ino);
      const bool seen = std::any_of(dirs.begin(), dirs.end(),
                                    [&](const auto& d) { return d.first == id; });
      if (seen) {
        ::close(fd);
        continue;
      }
      dirs.emplace_back(id, fd);
    }
    std::sort(dirs.begin(), dirs.end());
    for (const auto& d : dirs) {
      while (::flock(d.second, LOCK_EX) != 0 && errno == EINTR) {
      }
      fds_.push_back(d.second);
    }
  }
  DirectoryLocks(const DirectoryLocks&) = delete;
  DirectoryLocks& operator=(const DirectoryLocks&) = delete;
  ~DirectoryLocks() {
    for (int fd : fds_) ::close(fd);  // closing releases the lock
  }

 private:
  std::vector<int> fds_;
};

// Removes "<base>.dttmp-<pid>-..." beside `file` whose process no longer exists: what a run
// killed by SIGKILL (or a crash) left behind. A pid that is alive, or not ours to signal, is
// kept, so a concurrent run's temporaries are never touched.
void removeStaleTemporaries(const std::string& file) {
  const std::string dir = dirOf(file), prefix = baseOf(file) + ".dttmp-";
  DIR* d = ::opendir(dir.c_str());
  if (d == nullptr) return;
  while (const dirent* e = ::readdir(d)) {
    const std::string name = e->d_name;
    if (name.compare(0, prefix.size(), prefix) != 0) continue;
    const std::size_t dash = name.find('-', prefix.size());
    const std::string pid = name.substr(prefix.size(), dash - prefix.size());
    if (dash == std::string::npos || pid.empty() || pid.size() > 9 ||
        pid.find_first_not_of("0123456789") != std::string::npos)
      continue;
    const pid_t p = pid_t(std::atol(pid.c_str()));
    if (p == ::getpid() || p <= 0) continue;
    if (::kill(p, 0) != 0 && errno == ESRCH) ::unlinkat(::dirfd(d), name.c_str(), 0);
  }
  ::closedir(d);
}

}  // namespace

// ---- what an output is -----------------------------------------------------------------------

OutputTarget classifyOutput(const std::string& path) {
  OutputTarget t;
  t.path = path;
  if (path.empty()) throw OutputRefused("an output name is empty");
  if (path.back() == '/')
    throw OutputRefused(path + ": ends in '/', so it names a directory, not a file");
  struct stat st;
  const int fd = inheritedFd(path);
  if (fd >= 0) {
    if (::fstat(fd, &st) != 0)
      throw std::runtime_error(path + ": cannot write to descriptor " + std::to_string(fd) +
                               ": " + sysReason());
    if (S_ISDIR(st.st_mode)) refuse(path, path, st.st_mode);
    t.kind = OutputTarget::Stream;
    t.fd = fd;
    t.what = kindName(st.st_mode);
    return t;
  }
  bool viaProc = false;
  t.file = followLinks(path, viaProc);
  // A /proc descriptor entry (/dev/fd of another process...): written into, whatever it is.
  if (viaProc && ::stat(path.c_str(), &st) == 0 && !S_ISDIR(st.st_mode)) {
    t.kind = OutputTarget::Stream;
    t.what = kindName(st.st_mode);
    return t;
  }
  if (::stat(t.file.c_str(), &st) != 0) {
    // A new file, or a dangling symlink's target: created through a temporary. A path that
    // cannot be created (no such directory) fails when its temporary is opened, with the reason.
    t.what = "a new file";
    return t;
  }
  t.what = kindName(st.st_mode);
  if (S_ISREG(st.st_mode)) {
    t.exists = true;
    return t;
  }
  if (S_ISFIFO(st.st_mode) || S_ISCHR(st.st_mode)) {
    t.kind = OutputTarget::Stream;
    return t;
  }
  refuse(path, t.file, st.st_mode);
}

bool sameFile(const std::string& a, const std::string& b) {
  struct Key {
    bool exists = false;
    dev_t dev = 0;
    ino_t ino = 0;
    std::string name;
  };
  auto keyOf = [](const std::string& p) {
    Key k;
    struct stat st;
    const int fd = inheritedFd(p);
    if (fd >= 0 ? ::fstat(fd, &st) == 0 : ::stat(p.c_str(), &st) == 0) {
      k.exists = true;
      k.dev = st.st_dev;
      k.ino = st.st_ino;
      return k;
    }
    try {
      bool viaProc = false;
      k.name = canonicalNew(followLinks(p, viaProc));
    } catch (const std::runtime_error&) {
      k.name = canonicalNew(p);
    }
    return k;
  };
  const Key ka = keyOf(a), kb = keyOf(b);
  if (ka.exists && kb.exists) return ka.dev == kb.dev && ka.ino == kb.ino;
  if (ka.exists != kb.exists) return false;
  return ka.name == kb.name;
}

// ---- the set of outputs ----------------------------------------------------------------------

struct OutputFiles::File {
  OutputTarget target;
  std::string tmp;  // a File's temporary, until it is renamed
  int fd = -1;
  bool ownFd = true;  // false for an inherited descriptor (standard output)
  int slot = -1;
  std::unique_ptr<Writer> w;
};

void OutputFiles::setCommitHook(void (*hook)(std::size_t renamed)) { g_commitHook = hook; }

OutputFiles::~OutputFiles() { removeAll(); }

void OutputFiles::removeAll() {
  for (File* f : files_) {
    if (f->fd >= 0 && f->ownFd) ::close(f->fd);
    if (!f->tmp.empty()) ::unlink(f->tmp.c_str());
    unregisterTemporary(f->slot);
    delete f;
  }
  files_.clear();
}

Writer& OutputFiles::open(const std::string& path) {
  installHandlers();
  auto f = std::make_unique<File>();
  f->target = classifyOutput(path);
  const OutputTarget& t = f->target;
  if (t.kind == OutputTarget::Stream) {
    if (t.fd >= 0) {
      f->fd = t.fd;
      f->ownFd = false;
    } else {
      f->fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY |
                                       (t.what == std::string("a regular file") ? O_TRUNC : 0));
      if (f->fd < 0) throw std::runtime_error(path + ": cannot open for writing: " + sysReason());
    }
    // A reader that goes away must give EPIPE (reported, temporaries removed), not a silent
    // death by SIGPIPE.
    if (!g_sigpipeIgnored) {
      ignoreIfDefault(SIGPIPE);
      g_sigpipeIgnored = true;
    }
    f->w = std::make_unique<Writer>(f->fd, path, true);
    files_.push_back(f.release());
    return *files_.back()->w;
  }
  removeStaleTemporaries(t.file);
  struct stat old;
  const bool replacing = t.exists && ::stat(t.file.c_str(), &old) == 0;
  // Replacing by rename needs only the directory's permission; the file's owner expects it to
  // be changed only by those who may write it.
  if (replacing && ::faccessat(AT_FDCWD, t.file.c_str(), W_OK, AT_EACCESS) != 0)
    throw std::runtime_error(path + ": refusing to replace it: it could not be written in place (" +
                             sysReason() + ")");
  for (int k = 0;; ++k) {
    f->tmp = t.file + ".dttmp-" + std::to_string(::getpid()) + "-" + std::to_string(k);
    f->slot = registerTemporary(f->tmp);  // before it exists: a signal may come at any time
    f->fd = ::open(f->tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (f->fd >= 0) break;
    const int err = errno;
    unregisterTemporary(f->slot);
    f->slot = -1;
    if (err != EEXIST || k >= 100) {
      f->tmp.clear();
      throw std::runtime_error(path + ": cannot open for writing: " + std::strerror(err));
    }
  }
  if (replacing) {
    // The new file takes the old one's owner (root only can give it) and permission bits.
    if (::geteuid() == 0) (void)::fchown(f->fd, old.st_uid, old.st_gid);
    (void)::fchmod(f->fd, old.st_mode & 0777);
  }
  f->w = std::make_unique<Writer>(f->fd, path);
  files_.push_back(f.release());
  return *files_.back()->w;
}

bool OutputFiles::streamed(std::size_t i) const {
  return files_.at(i)->target.kind == OutputTarget::Stream;
}

std::vector<std::string> OutputFiles::temporaries() const {
  std::vector<std::string> t;
  for (const File* f : files_)
    if (!f->tmp.empty()) t.push_back(f->tmp);
  return t;
}

void OutputFiles::commit(AfterCommit after) {
  // The temporaries first, then the streams' last bytes: a File that fails leaves a stream with
  // less, and a stream that fails leaves every File unrenamed.
  for (bool streams : {false, true})
    for (File* f : files_) {
      if ((f->target.kind == OutputTarget::Stream) != streams) continue;
      f->w->flush();
      if (!f->ownFd) continue;
      const int rc = ::close(f->fd);
      f->fd = -1;
      if (rc != 0) throw std::runtime_error(f->target.path + ": cannot write: " + sysReason());
    }
  std::vector<File*> renamed;
  std::vector<std::string> targets;
  for (File* f : files_)
    if (f->target.kind == OutputTarget::File) {
      renamed.push_back(f);
      targets.push_back(f->target.file);
    }
  // Another run committing the same outputs waits here: the sets never interleave.
  const DirectoryLocks locks(targets);
  SignalsBlocked blocked;
  // A hard link to each file that is already there, so that a rename failing half way can
  // put back the ones replaced before it.
  std::vector<std::string> backup(renamed.size());
  for (std::size_t i = 0; i < renamed.size(); ++i) {
    struct stat st;
    if (::lstat(renamed[i]->target.file.c_str(), &st) != 0) continue;
    const std::string b = renamed[i]->tmp + "-old";
    if (::link(renamed[i]->target.file.c_str(), b.c_str()) == 0) backup[i] = b;
  }
  for (std::size_t i = 0; i < renamed.size(); ++i) {
    File* f = renamed[i];
    if (::rename(f->tmp.c_str(), f->target.file.c_str()) == 0) {
      f->tmp.clear();
      // From here on the commit is final: the signals that come are dropped or kept blocked.
      if (after == AfterCommit::KeepSignalsBlocked)
        blocked.keep();
      else
        blocked.dropPending();
      if (g_commitHook != nullptr) g_commitHook(i + 1);
      continue;
    }
    const std::string why = f->target.path + ": cannot rename the temporary file into place: " +
                            sysReason();
    for (std::size_t j = 0; j < i; ++j) {
      if (!backup[j].empty())
        ::rename(backup[j].c_str(), renamed[j]->target.file.c_str());
      else
        ::unlink(renamed[j]->target.file.c_str());
    }
    for (const std::string& b : backup)
      if (!b.empty()) ::unlink(b.c_str());
    throw std::runtime_error(why);
  }
  if (renamed.empty()) {  // streams only: they are complete, the commit is as final
    if (after == AfterCommit::KeepSignalsBlocked)
      blocked.keep();
    else
      blocked.dropPending();
  }
  for (const std::string& b : backup)
    if (!b.empty()) ::unlink(b.c_str());
  for (File* f : files_) {
    unregisterTemporary(f->slot);
    delete f;
  }
  files_.clear();
}

void writeFileAtomic(const std::string& path, const std::string& content) {
  OutputFiles out;
  out.open(path).put(content);
  out.commit();
}

}  // namespace dt
