// The viewer's camera saved as a scene: the scene file as written, its <sensor> carrying the
// values the viewer set (app/view/sensor_overrides.h) in place of the scene's (the pose as a
// to_world matrix, numbers written so that they read back to the same bits), and the film's
// size and exposure where the viewer changed them (its crop window left out, as the viewer
// shows the whole film), the sample count the viewer stopped at where it was given one, and
// the -D values the viewer was started with as the <default>s' values. Everything else stays as the file has it (comments and $names
// included), so `objektiv render` of the saved file renders the viewer's image. It is written beside the scene (its relative file names resolve from
// the scene's folder), atomically.
#pragma once
#include <map>
#include <optional>
#include <string>

#include "base/vec.h"
#include "app/view/sensor_overrides.h"

namespace objektiv {

struct SceneWithCamera {
  std::string scene_path;
  const SensorOverrides* sensor = nullptr;
  std::optional<Vec2i> film_size;  // the film's width and height, where the viewer changed them
  std::optional<double> exposure;  // the film's exposure (stops), where the viewer changed it
  std::map<std::string, std::string> defines;  // -D name=value
  bool whole_film = false;         // the scene's crop window left out (the viewer shows the whole film)
  std::optional<int> sample_count;  // the sampler's, where the viewer was given another (--spp)
};

// InputError naming the file when the scene's <sensor> is not in the scene file itself (it
// sits in an included file), when `xml_path` lies in another folder than the scene, or when
// it cannot be written.
void WriteSceneWithCamera(const SceneWithCamera& what, const std::string& xml_path);

}  // namespace objektiv
