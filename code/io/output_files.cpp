// The outputs of code/io/output_files.h: what a path is (classifyOutput, sameFile), temporaries
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
#include <sys/syscall.h>
#include <unistd.h>
#include <linux/fs.h>
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

// The lock file of an output directory. Every run that writes a file into the directory takes
// flock() on it: while it creates its temporaries and removes stale ones, and during its
// commit. A file, not the directory itself: opening a directory needs read permission, and a
// directory a run may write into (write and search) need not be readable.
constexpr const char* kLockName = ".dt-output.lock";
// Temporaries (and the link-made backups of the commit) are ".dttmp-<pid>-<k>" in the target's
// directory: short whatever the target's name, so that every name that fits NAME_MAX can be
// written and replaced.
constexpr const char* kTempPrefix = ".dttmp-";

// Opens (creating it if needed) the lock file of `dir`; -1 and errno if it cannot. Created
// readable by everyone (0444): any user who may write into the directory can then open it and
// lock it. O_NOFOLLOW and the regular-file check keep a planted symlink or pipe from being
// opened instead.
int openLockFile(const std::string& dir) {
  const std::string name = dir + "/" + kLockName;
  const int flags = O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC | O_NOCTTY;
  int fd = -1;
  for (int attempt = 0; attempt < 10 && fd < 0; ++attempt) {
    fd = ::open(name.c_str(), O_RDONLY | flags);
    if (fd < 0 && errno == EACCES) fd = ::open(name.c_str(), O_WRONLY | flags);
    if (fd >= 0 || errno != ENOENT) break;
    // Missing: created here (O_EXCL: if another run creates it at the same time, it is opened).
    fd = ::open(name.c_str(), O_RDONLY | O_CREAT | O_EXCL | flags, 0444);
    if (fd >= 0)
      (void)::fchmod(fd, 0444);  // whatever the umask: readable by all
    else if (errno != EEXIST)
      return -1;
  }
  if (fd < 0) return -1;
  struct stat st;
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd);
    errno = EINVAL;
    return -1;
  }
  return fd;
}

void lockExclusive(int fd) {
  while (::flock(fd, LOCK_EX) != 0 && errno == EINTR) {
  }
}

// The error of a lock that cannot be taken: the output named, with what the user can do.
[[noreturn]] void lockFailed(const std::string& path, const std::string& dir, int err) {
  // No directory to write into at all, or one the user may not write into: said as for the
  // file itself, since no lock is the matter.
  if (err == ENOENT || err == ENOTDIR || err == EROFS ||
      ::faccessat(AT_FDCWD, dir.c_str(), W_OK | X_OK, AT_EACCESS) != 0)
    throw std::runtime_error(path + ": cannot open for writing: " + std::strerror(err));
  throw std::runtime_error(path + ": cannot lock its directory through " + dir + "/" + kLockName +
                           ": " + std::strerror(err) +
                           " (it must be a regular file the user can open; if it is not, "
                           "remove it and the next run creates it)");
}

// The lock files of the targets' directories, each locked once, in (device, inode) order so
// that two processes locking overlapping sets cannot deadlock; released when destroyed.
class DirectoryLocks {
 public:
  /// targets[i] is written as paths[i] (for the message if a lock cannot be had).
  DirectoryLocks(const std::vector<std::string>& targets, const std::vector<std::string>& paths) {
    std::vector<std::pair<std::pair<dev_t, ino_t>, int>> locks;
    for (std::size_t i = 0; i < targets.size(); ++i) {
      const int fd = openLockFile(dirOf(targets[i]));
      struct stat st;
      if (fd < 0 || ::fstat(fd, &st) != 0) {
        const int err = errno;
        for (const auto& l : locks) ::close(l.second);
        lockFailed(paths[i], dirOf(targets[i]), err);
      }
      const std::pair<dev_t, ino_t> id(st.st_dev, st.st_ino);
      const bool seen = std::any_of(locks.begin(), locks.end(),
                                    [&](const auto& l) { return l.first == id; });
      if (seen) {  // a second descriptor of one lock file would wait for the first
        ::close(fd);
        continue;
      }
      locks.emplace_back(id, fd);
    }
    std::sort(locks.begin(), locks.end());
    for (const auto& l : locks) {
      lockExclusive(l.second);
      fds_.push_back(l.second);
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

// Removes the temporaries and backups (".dttmp-*") in `dir` that no live run holds: each run
// keeps flock() on its temporaries until its commit ends, so one that can be locked here was
// left by a run that ended without cleaning up (SIGKILL, a crash), whatever its pid says in
// this PID namespace or another. Called with the directory's lock held: no run is committing
// there (whose exchanged old files carry no lock) and none is creating a temporary. A directory
// that cannot be read is skipped.
void removeStaleTemporaries(const std::string& dir) {
  DIR* d = ::opendir(dir.c_str());
  if (d == nullptr) return;
  const std::size_t plen = std::strlen(kTempPrefix);
  while (const dirent* e = ::readdir(d)) {
    if (std::strncmp(e->d_name, kTempPrefix, plen) != 0) continue;
    struct stat held, now;
    // Only regular files are opened: opening a device can have effects of its own.
    if (::fstatat(::dirfd(d), e->d_name, &now, AT_SYMLINK_NOFOLLOW) != 0 || !S_ISREG(now.st_mode))
      continue;
    const int flags = O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC | O_NOCTTY;
    int fd = ::openat(::dirfd(d), e->d_name, O_RDONLY | flags);
    if (fd < 0 && errno == EACCES) fd = ::openat(::dirfd(d), e->d_name, O_WRONLY | flags);
    if (fd < 0) continue;  // not ours to judge (another user's, unreadable): kept
    if (::fstat(fd, &held) == 0 && S_ISREG(held.st_mode) && ::flock(fd, LOCK_EX | LOCK_NB) == 0 &&
        ::fstatat(::dirfd(d), e->d_name, &now, AT_SYMLINK_NOFOLLOW) == 0 &&
        now.st_dev == held.st_dev && now.st_ino == held.st_ino)
      ::unlinkat(::dirfd(d), e->d_name, 0);
    ::close(fd);
  }
  ::closedir(d);
}

// Why a run that is not root could not replace `file` in a sticky directory (empty if it can):
// there only the file's owner, the directory's owner and root may rename over or remove it, and
// a failed replacement would leave names behind that no one but them could remove.
std::string stickyRefusal(const std::string& file) {
  struct stat dst, fst;
  if (::geteuid() == 0 || ::stat(dirOf(file).c_str(), &dst) != 0 || !(dst.st_mode & S_ISVTX) ||
      ::lstat(file.c_str(), &fst) != 0)
    return "";
  if (fst.st_uid == ::geteuid() || dst.st_uid == ::geteuid()) return "";
  return "refusing to replace it: " + dirOf(file) +
         " is a sticky directory and the file belongs to user " + std::to_string(fst.st_uid) +
         ", so only that user (or the directory's owner) can replace it; ask them to remove it, "
         "or write to another name";
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

namespace {

// What sameFile compares: device and inode of an existing file, else the canonical name of the
// file the path would create.
struct FileKey {
  bool exists = false;
  dev_t dev = 0;
  ino_t ino = 0;
  std::string name;
  bool operator==(const FileKey& o) const {
    if (exists && o.exists) return dev == o.dev && ino == o.ino;
    return exists == o.exists && name == o.name;
  }
};

FileKey keyOf(const std::string& p) {
  FileKey k;
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
}

}  // namespace

bool sameFile(const std::string& a, const std::string& b) { return keyOf(a) == keyOf(b); }

OutputPlan planOutputs(const std::vector<OutputRequest>& list, const std::string& input) {
  OutputPlan plan;
  plan.requests = list;
  const FileKey in = keyOf(input == "-" ? "/dev/stdin" : input), out = keyOf("-");
  std::vector<FileKey> keys;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const OutputRequest& r = list[i];
    // A path that is no output names the option alone: the message goes on with the path.
    const std::string flag = r.option.substr(0, r.option.find(' '));
    try {
      plan.targets.push_back(classifyOutput(r.path));
    } catch (const OutputRefused& e) {
      throw OutputRefused(flag + " " + e.what());
    } catch (const std::exception& e) {
      throw std::runtime_error(flag + " " + e.what());
    }
    if (r.path == "-")
      for (std::size_t j = 0; j < i; ++j)
        if (list[j].path == "-")
          throw OutputConflict(list[j].option + " and " + r.option + " both write to standard output");
    keys.push_back(keyOf(r.path));
    if (keys[i] == out) plan.toStandardOutput = true;
    if (keys[i] == in)
      throw OutputRefused(r.option + ": " + r.path + " is the input file; refusing to overwrite it");
    for (std::size_t j = 0; j < i; ++j)
      if (keys[j] == keys[i])
        throw OutputRefused(list[j].option + " and " + r.option + " name the same file " + r.path);
  }
  return plan;
}

// ---- the set of outputs ----------------------------------------------------------------------

struct OutputFiles::File {
  OutputTarget target;
  std::string tmp;  // a File's temporary, until it is renamed
  int fd = -1;
  int lockFd = -1;    // a second descriptor of the temporary, holding flock() until the end
  bool ownFd = true;  // false for an inherited descriptor (standard output)
  int slot = -1;
  std::unique_ptr<Writer> w;
};

OutputFiles::OutputFiles(const OutputPlan& plan) {
  // A constructor that throws runs no destructor: the temporaries made so far go here.
  try {
    for (const OutputTarget& t : plan.targets) open(t);
  } catch (...) {
    removeAll();
    throw;
  }
}

Writer& OutputFiles::writer(std::size_t i) { return *files_.at(i)->w; }

Writer& OutputFiles::open(const std::string& path) { return open(classifyOutput(path)); }

OutputFiles::~OutputFiles() { removeAll(); }

void OutputFiles::removeAll() {
  for (File* f : files_) {
    if (f->fd >= 0 && f->ownFd) ::close(f->fd);
    if (!f->tmp.empty()) ::unlink(f->tmp.c_str());
    if (f->lockFd >= 0) ::close(f->lockFd);  // after the unlink: never a window without the lock
    unregisterTemporary(f->slot);
    delete f;
  }
  files_.clear();
}

Writer& OutputFiles::open(const OutputTarget& target) {
  installHandlers();
  auto f = std::make_unique<File>();
  f->target = target;
  const OutputTarget& t = f->target;
  const std::string& path = t.path;
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
  const std::string dir = dirOf(t.file);
  // The directory's lock, while stale temporaries are judged and this one is made and locked:
  // a temporary is never seen unlocked by another run's cleaning.
  const int lock = openLockFile(dir);
  if (lock < 0) lockFailed(path, dir, errno);
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closeLock{lock};
  lockExclusive(lock);
  removeStaleTemporaries(dir);
  struct stat old;
  const bool replacing = t.exists && ::stat(t.file.c_str(), &old) == 0;
  // Replacing by rename needs only the directory's permission; the file's owner expects it to
  // be changed only by those who may write it.
  if (replacing && ::faccessat(AT_FDCWD, t.file.c_str(), W_OK, AT_EACCESS) != 0)
    throw std::runtime_error(path + ": refusing to replace it: it could not be written in place (" +
                             sysReason() + ")");
  if (replacing) {
    const std::string why = stickyRefusal(t.file);
    if (!why.empty()) throw std::runtime_error(path + ": " + why);
  }
  for (int k = 0;; ++k) {
    f->tmp = dir + "/" + kTempPrefix + std::to_string(::getpid()) + "-" + std::to_string(k);
    f->slot = registerTemporary(f->tmp);  // before it exists: a signal may come at any time
    f->fd = ::open(f->tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (f->fd >= 0) break;
    const int err = errno;
    unregisterTemporary(f->slot);
    f->slot = -1;
    // EEXIST: a name of another run (another PID namespace may have the same pid) or ours.
    if (err != EEXIST || k >= 1000) {
      f->tmp.clear();
      throw std::runtime_error(path + ": cannot open for writing: " + std::strerror(err));
    }
  }
  // The mark of a live temporary: held until the commit ends (on a descriptor of its own, so
  // that closing the written one still reports a late write error).
  f->lockFd = ::dup(f->fd);
  if (f->lockFd < 0 || ::flock(f->lockFd, LOCK_EX | LOCK_NB) != 0) {
    const std::string why = sysReason();
    ::close(f->fd);
    if (f->lockFd >= 0) ::close(f->lockFd);
    ::unlink(f->tmp.c_str());
    unregisterTemporary(f->slot);
    throw std::runtime_error(path + ": cannot lock its temporary file: " + why);
  }
  if (replacing) {
    // The new file takes the old one's owner (root only can give it) and mode, set-group-ID
    // included (chown clears it, so it comes after; the kernel drops it where not allowed).
    if (::geteuid() == 0) (void)::fchown(f->fd, old.st_uid, old.st_gid);
    (void)::fchmod(f->fd, old.st_mode & 07777);
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

namespace {

// renameat2(2) by its system call (older C libraries lack the wrapper).
int renameFlags(const std::string& from, const std::string& to, unsigned flags) {
  return int(::syscall(SYS_renameat2, AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), flags));
}

// A file system (or kernel) without that flag of renameat2.
bool unsupported(int err) { return err == EINVAL || err == ENOSYS || err == EOPNOTSUPP; }

}  // namespace

void OutputFiles::commit(AfterCommit after, const OutputHooks& hooks) {
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
  std::vector<std::string> targets, paths;
  for (File* f : files_)
    if (f->target.kind == OutputTarget::File) {
      renamed.push_back(f);
      targets.push_back(f->target.file);
      paths.push_back(f->target.path);
    }
  // Another run committing into the same directories waits here: the sets never interleave.
  const DirectoryLocks locks(targets, paths);
  SignalsBlocked blocked;
  // How each target was put in place, so that a later failure can take it back:
  //   Created   there was no file: the new one is removed;
  //   Exchanged renameat2(RENAME_EXCHANGE): the old file is now under the temporary's name;
  //   Linked    (file systems without the exchange) a hard link `backup` to the old file was
  //             made before the rename; if it cannot be made, nothing of this file is touched.
  enum How { Pending, Created, Exchanged, Linked };
  std::vector<How> how(renamed.size(), Pending);
  std::vector<std::string> backup(renamed.size());
  // A target that is no longer a regular file (a directory made meanwhile) is not exchanged
  // (an exchange would put the directory under the temporary's name): checked for all before
  // the first rename, and again just before each.
  auto notRegular = [](const File* f, struct stat& st) {
    return ::lstat(f->target.file.c_str(), &st) == 0 && !S_ISREG(st.st_mode);
  };
  auto nowWhat = [](const File* f, const struct stat& st) {
    return f->target.path + ": cannot replace it: it is now " + kindName(st.st_mode);
  };
  for (const File* f : renamed) {
    struct stat st;
    if (notRegular(f, st)) throw std::runtime_error(nowWhat(f, st));
  }
  std::string why;
  std::size_t done = 0;
  for (; done < renamed.size() && why.empty(); ++done) {
    File* f = renamed[done];
    const std::string& to = f->target.file;
    const std::string fail = f->target.path + ": cannot rename the temporary file into place: ";
    struct stat st;
    if (notRegular(f, st)) {
      why = nowWhat(f, st);
      break;
    }
    if (::lstat(to.c_str(), &st) != 0) {
      // None there: never put over one that appeared meanwhile (it would be lost on a rollback).
      int rc = renameFlags(f->tmp, to, RENAME_NOREPLACE);
      if (rc != 0 && unsupported(errno)) rc = ::rename(f->tmp.c_str(), to.c_str());
      if (rc != 0) {
        why = fail + sysReason();
        break;
      }
      how[done] = Created;
    } else if (renameFlags(f->tmp, to, RENAME_EXCHANGE) == 0) {
      how[done] = Exchanged;  // f->tmp now names the old file
    } else if (!unsupported(errno)) {
      why = fail + sysReason();
      break;
    } else {
      const std::string b = f->tmp + "-old";
      ::unlink(b.c_str());  // a stale one (the directory is locked: no commit is under way)
      if (::link(to.c_str(), b.c_str()) != 0) {
        why = f->target.path + ": cannot keep a copy of the old file before replacing it (" +
              sysReason() + "): nothing was replaced";
        break;
      }
      backup[done] = b;
      if (::rename(f->tmp.c_str(), to.c_str()) != 0) {
        why = fail + sysReason();
        ::unlink(b.c_str());
        backup[done].clear();
        break;
      }
      how[done] = Linked;
    }
    if (how[done] != Exchanged) f->tmp.clear();
    // From here on the commit is final: the signals that come are dropped or kept blocked.
    if (after == AfterCommit::KeepSignalsBlocked)
      blocked.keep();
    else
      blocked.dropPending();
    if (hooks.afterRename) hooks.afterRename(done + 1);
  }
  if (!why.empty()) {
    // Put back, newest first, what was replaced. An old file whose restore fails is kept under
    // its temporary or backup name, and the message says where.
    std::string lost;
    for (std::size_t j = done; j-- > 0;) {
      File* f = renamed[j];
      const std::string& to = f->target.file;
      bool ok = true;
      if (how[j] == Created) {
        ok = ::unlink(to.c_str()) == 0;
      } else if (how[j] == Exchanged) {
        ok = renameFlags(f->tmp, to, RENAME_EXCHANGE) == 0;  // the new file is the temporary again
        if (!ok) lost += "; the old " + f->target.path + " is kept as " + f->tmp;
      } else if (how[j] == Linked) {
        ok = ::rename(backup[j].c_str(), to.c_str()) == 0;
        if (!ok) lost += "; the old " + f->target.path + " is kept as " + backup[j];
      }
      if (!ok) {
        f->tmp.clear();  // never removed: it holds an old file (or the restore failed)
        backup[j].clear();
      }
    }
    throw std::runtime_error(why + lost);  // removeAll deletes the temporaries left
  }
  if (renamed.empty()) {  // streams only: they are complete, the commit is as final
    if (after == AfterCommit::KeepSignalsBlocked)
      blocked.keep();
    else
      blocked.dropPending();
  }
  for (const std::string& b : backup)
    if (!b.empty()) ::unlink(b.c_str());
  removeAll();  // the old files under the temporaries' names, the locks of the new ones
}

void writeFileAtomic(const std::string& path, const std::string& content) {
  OutputFiles out;
  out.open(path).put(content);
  out.commit();
}

}  // namespace dt
