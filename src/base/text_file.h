// Reading text input files: whole-file reads with clear errors, UTF-16 or UTF-8 byte-order
// marks, and strict number parsing (the whole token, finite).
#pragma once
#include <optional>
#include <string>
#include <vector>

namespace objektiv {

// The file's bytes; throws InputError "PATH: cannot open WHAT" if it cannot be read. The file
// is recorded as an input of this run (base/input_files.h).
std::string ReadTextFile(const std::string& path, const char* what);
// UTF-16 (either byte order, with a byte-order mark) to ASCII ('?' for other characters);
// a UTF-8 byte-order mark is dropped; anything else is returned unchanged.
std::string DecodeToAscii(const std::string& raw);
// The number spelled by the whole of `s` (surrounding spaces allowed), if finite.
std::optional<double> ParseFiniteNumber(const std::string& s);
// The same, or InputError "PATH:LINE: 'S' is not a finite number".
double ParseFiniteNumber(const std::string& s, const std::string& path, int line);
// The whitespace-separated fields of one line (a trailing '\r' is whitespace too).
std::vector<std::string> SplitFields(const std::string& line);

}  // namespace objektiv
