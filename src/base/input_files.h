// The files this process has read as input (scene, includes, meshes, images, lens files, glass
// catalogs), by canonical path with symlinks followed, so that no output replaces one of them:
// every reader of user files records what it opens here, and the output writer asks.
#pragma once
#include <optional>
#include <string>

namespace objektiv {

// Notes that `path` was read. Thread-safe.
void RecordInputFile(const std::string& path);
// The recorded input (its path as the reader was given it) that a file written at `path`
// would replace: the same canonical path, or the same file reached through another name.
std::optional<std::string> InputFileAt(const std::string& path);

}  // namespace objektiv
