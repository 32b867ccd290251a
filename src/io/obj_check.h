// An OBJ file checked before tinyobjloader reads it. tinyobjloader reads a token that is not a
// number as 0 and an index that is not an integer as no index, without a word: `v 1 x 3` would
// put a vertex at y = 0. Here every value of a `v`, `vn` and `vt` line must be a finite
// number (3 to 7, 3, and 1 to 3 of them), and every corner of an `f`, `l` or `p` line an index
// (`i`, `i/t`, `i//n`, `i/t/n`; negative counts back from the end) or the error names the file
// and line. Other statements (groups, smoothing, materials) pass unchecked.
#pragma once
#include <string>

namespace objektiv {

// Throws InputError "PATH:LINE: ..." for the first malformed statement of `text`.
void CheckObjText(const std::string& text, const std::string& path);

}  // namespace objektiv
