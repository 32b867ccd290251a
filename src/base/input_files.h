// The files this process has read as input (scene, includes, meshes, images, lens files, glass
// catalogs), by canonical path with symlinks followed, so that no output replaces one of them:
// every reader of user files records what it opens here, and the output writer asks.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace objektiv {

// Notes that `path` was read. Thread-safe.
void RecordInputFile(const std::string& path);
// The recorded input (its path as the reader was given it) that a file written at `path`
// would replace: the same canonical path, or the same file reached through another name.
std::optional<std::string> InputFileAt(const std::string& path);
// Every recorded input, by canonical path (sorted).
std::vector<std::string> InputFiles();
// A 64-bit hash of the contents of every recorded input, independent of their paths and of the
// order they were read in (FNV-1a per file, the files' hashes sorted and hashed again): the
// same scene with the same files on another machine, or after a copy, hashes the same.
// Throws InputError naming a file that can no longer be read.
uint64_t InputFilesContentHash();
// Each recorded input's content hash (FNV-1a), by canonical path (sorted by path), and the
// hash of such a list as InputFilesContentHash makes it.
std::vector<std::pair<std::string, uint64_t>> InputFilesContentHashes();
uint64_t CombinedContentHash(const std::vector<std::pair<std::string, uint64_t>>& files);

}  // namespace objektiv
