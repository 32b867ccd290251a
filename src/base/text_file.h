// Reading input files: the check every reader of user files makes first (a regular file
// within a size limit: a directory, FIFO or device such as /dev/zero could be read without
// end), whole-file text reads with clear errors, UTF-16 or UTF-8 byte-order marks, and strict
// number parsing (the whole token, finite).
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace objektiv {

// Largest text input read whole: a scene or included file, a lens file, a glass catalog.
inline constexpr uintmax_t kMaxTextFileBytes = uintmax_t(64) << 20;

// The size of the file `path` names; throws InputError "PATH: cannot read WHAT: ..." unless
// it is an existing regular file (symbolic links followed) of at most max_bytes.
uintmax_t CheckInputFile(const std::string& path, const char* what, uintmax_t max_bytes);
// The file's bytes (checked by CheckInputFile, and no more than its size then are read);
// throws InputError naming the file if it cannot be read. The file is recorded as an input of
// this run (base/input_files.h).
std::string ReadTextFile(const std::string& path, const char* what, uintmax_t max_bytes = kMaxTextFileBytes);
// UTF-16 (either byte order, with a byte-order mark) to ASCII ('?' for other characters);
// a UTF-8 byte-order mark is dropped; anything else is returned unchanged.
std::string DecodeToAscii(const std::string& raw);
// The number spelled by the whole of `s` (surrounding spaces allowed), if finite.
std::optional<double> ParseFiniteNumber(const std::string& s);
// The same, or InputError "PATH:LINE: 'S' is not a finite number".
double ParseFiniteNumber(const std::string& s, const std::string& path, int line);
// The integer in [lo, hi] spelled by the whole of `s` ("7", or "7.0" as some files write it),
// range-checked in floating point before it is converted (a double beyond an int's range
// must not reach the conversion).
std::optional<int> ParseIntegerIn(const std::string& s, int lo, int hi);
// The whitespace-separated fields of one line (a trailing '\r' is whitespace too).
std::vector<std::string> SplitFields(const std::string& line);
// A token from a file as a message may show it: bytes outside printable ASCII as \xNN (raw
// bytes of a binary file would garble the terminal, a NUL cut the message), at most 60
// characters of it followed by "...".
std::string Printable(const std::string& token);

}  // namespace objektiv
