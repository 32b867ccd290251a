// The end of a render, shared by `render` and `merge`: the film made for a scene's settings,
// its image composed with the lens's layers and written (EXR and PNG), and what identifies a
// render so that its parts can be put together (render parts: io/render_part.h).
#pragma once
#include <CLI/CLI.hpp>

#include <map>
#include <string>
#include <vector>

#include "io/image_io.h"
#include "io/render_part.h"
#include "io/scene_loader.h"
#include "render/film.h"
#include "render/lens_layers.h"

namespace objektiv {

// An output file and what it is, for messages.
struct Output {
  std::string what, path;
};
// Bad outputs are bad command-line values (CLI::ValidationError, exit status 2), found before
// the long work. Before the scene is loaded: every output can be written (its directory exists;
// it is not created, so that a mistyped path fails instead of growing directories) and no two
// are one file.
void CheckOutputsWritable(const std::vector<Output>& outputs);
// After the inputs are read: no output replaces one (`read_by`: who reads them, for the message).
void CheckOutputsAreNotInputs(const std::vector<Output>& outputs, const char* read_by = "the scene");

// The film of a loaded scene (its crop window as set up), once its memory and the effects'
// fit `budget_gib` (else InputError at the film's line); the emitted light and the AOVs kept
// where the camera and the integrator need them.
Film MakeRenderFilm(const RenderSetup& setup, double budget_gib, int threads);

// Composes the lens's layers over the film (render/lens_layers.h) on at most `threads` threads
// (0: all), and writes the linear EXR (the picture, the layers, the AOVs; `header` and what the
// passes did) and the tone-mapped PNG, both atomically. Ctrl-C during the passes (they stop
// early) marks the image objektiv:partial = 1, render_end "interrupted". Returns the layers.
// With `sample_count_layer`, a channel `sample_count` after the others: each pixel's camera
// samples (where adaptive sampling spent them; not for an anaglyph, whose pixels mix both eyes':
// warned).
LensLayers WriteRenderImages(const RenderSetup& setup, const Film& film, int threads, const std::string& exr,
                             const std::string& png, std::vector<ImageAttribute> header,
                             bool sample_count_layer = false);
// Channels `names` (values interleaved per pixel) after the image's own.
void AppendChannels(const std::vector<std::string>& names, const std::vector<float>& values, Image& image);

// The lens passes' times after the render's, for the summary line: " + bright points and
// ghosts 3.40 s + diffraction 1.15 s".
std::string LensPassTimes(const LensLayers& layers);

// What a part of this render is a part of (RenderPartInfo's first fields), right after the scene
// is loaded: the scene's path made absolute, the hash of the files read so far (the scene's),
// the -D values as JSON, and the sampler's spp and seed as set up.
RenderPartInfo DescribeRender(const std::string& scene, const std::map<std::string, std::string>& defines,
                              const RenderSetup& setup);
// -D values back from DescribeRender's JSON; InputError naming `part` if it is not an object of strings.
std::map<std::string, std::string> DefinesFromJson(const std::string& json, const std::string& part);

}  // namespace objektiv
