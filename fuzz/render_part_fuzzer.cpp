// Fuzz harness: render parts and checkpoints (io/render_part.h) as `objektiv merge` and
// `render --resume` read them: the header, the check that parts make one render, the sums,
// and adding them to a film of the part's size (a part whose planes do not fit is refused with
// std::invalid_argument, which merge turns into an error naming the file).
#include <stdexcept>

#include "fuzz_support.h"
#include "io/render_part.h"
#include "io/render_part_set.h"
#include "render/filter.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace objektiv;
  fuzz::Quiet();
  const std::string path = fuzz::WriteScratchFile("part.exr", fuzz::Bytes(data, size));
  fuzz::IgnoringInputErrors([&] {
    const RenderPartInfo info = ReadRenderPartInfo(path);
    try {
      CheckPartsMakeOneRender({path}, {info});
    } catch (const InputError&) {
    }
    const RenderPart part = ReadRenderPart(path);
    Film film(part.info.width, part.info.height, part.acc.crop, std::make_shared<BoxFilter>(0.5f));
    try {
      film.AddAccumulators(part.acc);
    } catch (const std::invalid_argument&) {
      return;
    }
    AddRenderPart(path, film);  // the strip by strip reader, as merge uses it
    film.Xyz();
    film.samples_per_pixel();
  });
  return 0;
}
