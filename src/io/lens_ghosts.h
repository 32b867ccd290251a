// The ghosts of a distant bright point as the sensor records them (`objektiv lens ghosts`): the
// two-reflection ghosts of the lens as set up (stop, blades, coatings), each found by its ray
// bundle (optics/ghosts.h), drawn at one wavelength or for white light, with each ghost's share
// of the light: its flux over the light the point sends onto the front element (so the point's
// own image has a share below 1 too: the lens's transmittance and vignetting). A pixel holds
// the share that the ghosts put on it; for white light, its luminance (Y) does (the RGB of a
// saturated colour may have a negative channel).
#pragma once
#include <optional>
#include <vector>

#include "base/image.h"
#include "optics/ghosts.h"

namespace objektiv {

struct GhostPictureRequest {
  double field_deg = 10, azimuth_deg = 0;  // where the point lies: angle from the axis, and toward (0: the image's left)
  double sensor_width = 36, sensor_height = 24;  // mm
  int width = 768;                         // pixels; the height follows the sensor's aspect
  int grid = 64;                           // rays per side of each bundle
  std::optional<double> lambda_nm;         // one wavelength, or white light (400..700 nm)
};

struct GhostShare {
  Ghost ghost;
  double share = 0;  // of the point's light (luminance-weighted for white light)
};

struct GhostPicture {
  Image image;
  std::vector<GhostShare> ghosts;  // brightest first
  double total_share = 0;
  double direct_share = 0;  // the point's own image (luminance-weighted for white light)
};

GhostPicture PictureGhosts(const LensSystem& lens, const GhostPictureRequest& request);

}  // namespace objektiv
