// A set of output files written all or nothing, and what an output path is (a file to replace
// through a temporary, a stream to write into, or something to refuse).
#pragma once

#include <cstddef>
#include <functional>
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

/// Outputs that cannot go together as asked: two of them on standard output (a usage error of
/// the caller, where the other refusals are about what a path is).
struct OutputConflict : OutputRefused {
  using OutputRefused::OutputRefused;
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

/// One output a caller asks for: the option that asks for it, as messages name it ("--svg",
/// "-o mesh"), and its path.
struct OutputRequest {
  std::string option;
  std::string path;
};

/// The outputs of one run, each path classified once, in the order they were asked for.
struct OutputPlan {
  std::vector<OutputRequest> requests;
  std::vector<OutputTarget> targets;  ///< targets[i]: what requests[i].path is
  bool toStandardOutput = false;      ///< an output is standard output (report elsewhere)
};

/// Classifies every path of `list` once (classifyOutput), before anything is read or written,
/// and refuses what cannot be written as asked, naming the option: OutputRefused for a path no
/// output may be written to, for an output that is the file `input` ("-": standard input) and
/// for two outputs that are the same file (sameFile); OutputConflict for two outputs on "-";
/// std::runtime_error (the option, the path, the system's reason) for a path that cannot be
/// classified.
OutputPlan planOutputs(const std::vector<OutputRequest>& list, const std::string& input);

/// Where a test steps into a commit: `afterRename` is called after each rename with the number
/// done so far, with the cleanup signals blocked and the lock held (a test pauses there to send
/// a signal or to start a concurrent run). Empty, as a program passes it: nothing is called.
struct OutputHooks {
  std::function<void(std::size_t renamed)> afterRename;
};

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
  /// Opens every output of `plan` as planned (no path is classified again), in its order.
  explicit OutputFiles(const OutputPlan& plan);
  OutputFiles(const OutputFiles&) = delete;
  OutputFiles& operator=(const OutputFiles&) = delete;
  ~OutputFiles();  ///< removes the temporaries not committed
  /// Classifies `path` (classifyOutput) and opens it as open(const OutputTarget&) does.
  Writer& open(const std::string& path);
  /// Creates the temporary of a classified output or opens its stream, and returns a Writer on
  /// it (valid until commit). Throws OutputRefused or std::runtime_error.
  Writer& open(const OutputTarget& target);
  /// The Writer of output i (in the order of open, or of the plan).
  Writer& writer(std::size_t i);
  /// Whether output i (in the order of open) is a Stream.
  bool streamed(std::size_t i) const;
  /// Sends every stream's last bytes and closes every temporary, then (locked, cleanup signals
  /// blocked) renames the temporaries into place, calling `hooks` as it goes.
  void commit(AfterCommit after = AfterCommit::RestoreSignals, const OutputHooks& hooks = {});
  /// The temporary file names (for tests and messages).
  std::vector<std::string> temporaries() const;

 private:
  struct File;
  void removeAll();
  std::vector<File*> files_;
};

}  // namespace dt
