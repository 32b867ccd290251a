// Output files: checked before long work starts, written atomically, never over an input.
//
// An output is written to a temporary file in its own directory, flushed to disk and renamed
// over the target. A rename within one file system is atomic, so whoever opens the target
// (or finds it after a kill, a Ctrl-C or a full disk) sees the old file or the whole new one,
// never a truncated file behind a valid header. A target that is a symbolic link is written
// where the link points (the link stays). No output may replace a file this process read as
// input (see base/input_files.h).
#pragma once
#include <functional>
#include <string>
#include <string_view>

namespace objektiv {

// Throws InputError "PATH: what is wrong" unless a file can be written at `path`: its
// directory exists (it is not created) and lets us create a file (probed by creating and
// removing a temporary file there), and `path` is not a directory, a read-only file or a file
// this process has read as input.
void CheckOutputFile(const std::string& path);

// Writes `path` atomically: `fill` writes the temporary file named by its argument (it may
// open it by name and truncate it); then the temporary replaces `path`. If `fill` throws,
// the temporary is removed and the exception passes on. Throws InputError naming `path` if
// the temporary cannot be made or renamed, or `path` is a file read as input.
void WriteFileAtomically(const std::string& path, const std::function<void(const std::string& temp)>& fill);
void WriteTextFileAtomically(const std::string& path, std::string_view text);

// Removes the temporaries of `path` left by processes of this machine that no longer run
// (killed while writing it, e.g. a render's checkpoint). Others' are left alone.
void RemoveStaleTemporaries(const std::string& path);

// For a signal handler that ends the process: removes the temporary file being written, if
// any. Async-signal-safe.
void RemovePendingTemporaryFile();

}  // namespace objektiv
