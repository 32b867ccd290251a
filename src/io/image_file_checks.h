// Checks of an image file's structure that its decoder does not make, run around
// OpenImageIO: libjpeg decodes a truncated JPEG with a warning only (the missing rows grey)
// and OpenImageIO reports success; OpenEXR allocates whatever size an attribute's header
// claims (2 GiB from a file of a few kilobytes) before finding the file too short.
#pragma once
#include <cstdint>
#include <string>

namespace objektiv {

// Whether a JPEG file runs to its end-of-image marker. The walk skips each marker segment by
// its length (an embedded thumbnail's own marker does not count) and, in entropy-coded
// data, stuffed 0xFF bytes and restart markers.
bool JpegIsComplete(const std::string& path);

// Throws InputError "PATH: ..." unless every header of an OpenEXR file of `file_size` bytes
// (one, or several for a multi-part file) is a list of attributes (name, type, size, value)
// that each fit in the file.
void CheckExrHeaders(const std::string& path, uintmax_t file_size);

}  // namespace objektiv
