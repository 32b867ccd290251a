// Render parts and checkpoints: an EXR that holds what a film accumulated, exactly, so that
// parts of one render (sample ranges, crops) merge into it bit for bit (`objektiv merge`) and
// a stopped render goes on where it stopped (`--resume`).
//
// The file is an ordinary EXR: R, G, B are the part's own image (what its samples show, to
// look at), and beside them the film's accumulators (render/film.h, FilmAccumulators):
// `state.count` (uint32, each pixel's samples) and per plane P four uint32 channels
// `state.P.0` to `state.P.3`, the bits of the exact sum's two doubles (hi low word, hi high
// word, lo low word, lo high word). The header says what it is a part of (RenderPartInfo,
// attributes `objektiv:...`), so that parts of other scenes or settings are refused.
#pragma once
#include <cstdint>
#include <string>

#include "base/image.h"
#include "render/film.h"

namespace objektiv {

struct RenderPartInfo {
  // The render it is a part of: each must agree across parts (Mismatch).
  std::string version;      // of objektiv
  std::string scene;        // the scene file's absolute path (merge loads it from there)
  std::string scene_hash;   // 16 hex digits: the contents of every file the scene read (base/input_files.h)
  std::string inputs;       // those files, a line each: 16 hex digits of its contents' hash, its name
                            // (relative to the scene's folder where inside it), to say which changed
  std::string defines;      // the -D values, as a JSON object
  int spp = 0;              // the render's samples per pixel
  uint64_t seed = 0;        // the sampler's
  std::string sampling;     // its pattern and adaptive settings (DescribeSampling; "" for none)
  int width = 0, height = 0;  // the film
  CropWindow render_crop;   // the render's pixels (the scene's crop window: all parts together)
  // This part.
  CropWindow crop;          // its pixels
  int spp_begin = 0, spp_end = 0;  // its sample indices
  bool checkpoint = false;  // a checkpoint (some pixels may lack samples), not a finished part
  double seconds = 0;       // rendering time so far
  uint64_t pixels_completed = 0;  // pixels with every sample of [spp_begin, spp_end)

  bool Complete() const { return pixels_completed == uint64_t(crop.Width()) * crop.Height(); }
  // "" if `o` is a part of the same render, else which setting differs, with both values.
  std::string Mismatch(const RenderPartInfo& o) const;
  // Which of the scene's files differ between this and `o` (changed, or read by one only).
  std::string ChangedInputs(const RenderPartInfo& o) const;
};

// Writes what `film` holds (its crop window; `rgb` its image to show) atomically
// (base/output_file.h), a strip of rows at a time. Throws InputError naming `path`.
void WriteRenderPart(const std::string& path, const Image& rgb, const Film& film, const RenderPartInfo& info);

// The header only (cheap: to check parts before reading any pixels). Throws InputError
// "PATH: ..." for a file that is not a render part of this version's format.
RenderPartInfo ReadRenderPartInfo(const std::string& path);

struct RenderPart {
  RenderPartInfo info;
  FilmAccumulators acc;
};
// Header and accumulators; the plane names come from the file. Throws InputError "PATH: ...".
RenderPart ReadRenderPart(const std::string& path);
// Adds a part's sums to `film` a strip of rows at a time (no copy of the whole part in memory):
// InputError "PATH: ..." for a bad file, or one whose planes or pixels are not the film's.
// Returns its header.
RenderPartInfo AddRenderPart(const std::string& path, Film& film);

}  // namespace objektiv
