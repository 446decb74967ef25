// A set of output files written all or nothing, and what an output path is (a file to replace
// through a temporary, a stream to write into, or something to refuse).
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "writers.h"

namespace dt {

/// An output path that names something no output may be written to: a directory, a socket, a
/// block device. what() is one line naming the path and what it is.
struct OutputRefused : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// What an output path is, decided with lstat and stat before anything is written.
struct OutputTarget {
  enum Kind {
    File,    ///< a regular file or a path still to be created: temporary beside it, then rename
    Stream,  ///< a named pipe, a character device or standard output: written straight into
  };
  Kind kind = File;
  std::string path;  ///< as given
  /// File: the path the temporary is renamed onto: `path`, or the file a symlink finally points
  /// to (created if the link dangles). Stream: the path to open, empty when `fd` is used.
  std::string file;
  int fd = -1;          ///< Stream: an inherited descriptor ("-" and /dev/stdout: 1, /dev/stderr: 2)
  bool exists = false;  ///< File: whether `file` exists (it is replaced)
  std::string what;     ///< "a regular file", "a named pipe", "a character device", ...
};

/// Decides how `path` is written: "-", /dev/stdout, /dev/stderr and /dev/fd/N are the inherited
/// descriptors; a symlink is followed to its final target (a dangling one to the file it would
/// create); a named pipe or a character device is a Stream; a regular file or a missing path a
/// File. Throws OutputRefused for a directory, a socket or a block device, and for a name ending
/// in '/'. Throws std::runtime_error (with the system's reason) if a symlink cannot be followed.
OutputTarget classifyOutput(const std::string& path);

/// Whether two paths name the same file: device and inode for existing files (following
/// symlinks; "-" is standard output), the canonical parent directory and the name of the file a
/// path would create (following a dangling symlink) otherwise.
bool sameFile(const std::string& a, const std::string& b);

/// Writes `content` to `path` through a temporary file renamed into place, so that a failure
/// leaves no partial file. Throws std::runtime_error naming the path and the system's reason.
void writeFileAtomic(const std::string& path, const std::string& content);

/// A set of outputs written all or nothing, as far as the kind of each allows:
/// - a File is written to a temporary ".dttmp-<pid>-<k>" in its target's directory (a short
///   name: any target whose name fits NAME_MAX can be written); commit() puts them all in place
///   only when all are written, holding flock() on the lock file ".dt-output.lock" of each
///   target directory (a file: the directory need not be readable), so that two processes'
///   sets never mix. An existing target is swapped with its temporary (renameat2
///   RENAME_EXCHANGE; where the file system lacks it, a hard link to the old file is made
///   first, and if it cannot be, nothing is replaced), so that a failure half way puts every
///   old file back; a new target is never put over a file that appeared meanwhile. A replaced
///   file keeps its mode, set-group-ID included (and, for root, its owner); a target the
///   process could not write in place, or could not replace in a sticky directory, is refused
///   before anything is written. A replaced file is a new inode: another hard link to the old
///   file keeps the old content (as after `mv`).
/// - a Stream is written straight into (it cannot be taken back); commit() sends its last bytes
///   before any rename, so a stream that fails leaves every File as it was.
/// Until the first rename, a failure, an exception or SIGINT/SIGTERM/SIGHUP removes the
/// temporaries and leaves every pre-existing file as it was; from the first rename on (with
/// streams only: once they are sent), the commit is final: those signals no longer end the
/// process during the commit (see AfterCommit). SIGXFSZ is ignored (an oversized write fails with EFBIG) and so is SIGPIPE
/// while a stream is open (a closed pipe fails with EPIPE). Each temporary carries flock()
/// while its run lives; open() removes the ".dttmp-*" of its directory that no one holds (left
/// by a run killed with SIGKILL, in this PID namespace or another), if the directory is readable.
class OutputFiles {
 public:
  /// What commit() does with SIGINT/SIGTERM/SIGHUP once the outputs are in place: drop those
  /// that came during the renames and restore the mask (the default), or keep them blocked for
  /// the rest of the process, so that a program that still reports and exits cannot be turned
  /// into a failure by a signal after its outputs are final.
  enum class AfterCommit { RestoreSignals, KeepSignalsBlocked };

  OutputFiles() = default;
  OutputFiles(const OutputFiles&) = delete;
  OutputFiles& operator=(const OutputFiles&) = delete;
  ~OutputFiles();  ///< removes the temporaries not committed
  /// Classifies `path` (classifyOutput), creates its temporary or opens its stream, and returns
  /// a Writer on it (valid until commit). Throws OutputRefused or std::runtime_error.
  Writer& open(const std::string& path);
  /// Whether output i (in the order of open) is a Stream.
  bool streamed(std::size_t i) const;
  /// Sends every stream's last bytes and closes every temporary, then (locked, cleanup signals
  /// blocked) renames the temporaries into place.
  void commit(AfterCommit after = AfterCommit::RestoreSignals);
  /// The temporary file names (for tests and messages).
  std::vector<std::string> temporaries() const;
  /// Tests only: called inside commit() after each rename with the number done so far, with
  /// the cleanup signals blocked and the lock held (a test pauses there to send a signal or to
  /// start a concurrent run). nullptr (the default) for none.
  static void setCommitHook(void (*hook)(std::size_t renamed));

 private:
  struct File;
  void removeAll();
  std::vector<File*> files_;
};

}  // namespace dt
