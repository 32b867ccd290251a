// Checks of an image file's structure that its decoder does not make, run around
// OpenImageIO: libjpeg decodes a truncated JPEG with a warning only (the missing rows grey)
// and OpenImageIO reports success; OpenEXR allocates whatever size an attribute's header
// claims (2 GiB from a file of a few kilobytes) before finding the file too short;
// its BMP reader decodes a run-length-coded file inside open(), into width x height bytes
// before anything checked the header's claim.
#pragma once
#include <cstdint>
#include <optional>
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

// The width and height (its absolute value: negative means top-down rows) a BMP file's
// information header claims, read as OpenImageIO reads them (32-bit fields, or 16-bit in an
// OS/2 1.x header); nullopt for a file too short to hold them or a header of another size,
// which OpenImageIO refuses itself. OpenImageIO multiplies the two in an int for a
// run-length-coded file: a claim of 50000 x 50000 asks std::vector for a negative size
// (std::length_error, found by fuzz_image), so the claim is checked before it opens the file.
struct ImageSize {
  int64_t width = 0, height = 0;
};
std::optional<ImageSize> BmpClaimedSize(const std::string& path);

}  // namespace objektiv
