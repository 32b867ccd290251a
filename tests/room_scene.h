// The diffuse room several integrator comparisons render: a box of diffuse walls (white, the
// left one red) open toward the camera, a white diffuse sphere on its floor, the caller's light
// inside, seen through the caller's sensor, kSize x kSize pixels (image_estimates.h).
#pragma once
#include <fmt/format.h>

#include <string>

#include "image_estimates.h"

namespace objektiv::test {

// `integrator`: the whole <integrator> element; `sensor`: the sensor's opening tag and its own
// properties (the room adds its transform, sampler and film and closes it).
inline std::string DiffuseRoom(const std::string& integrator, const std::string& sensor, const std::string& light,
                               int spp, int seed) {
  return fmt::format(R"(<scene version="3.0.0">
  {}
  {}
    <transform name="to_world"><lookat origin="0, 1, 3.2" target="0, 1, 0" up="0, 1, 0"/></transform>
    <sampler type="independent"><integer name="sample_count" value="{}"/><integer name="seed" value="{}"/></sampler>
    <film type="hdrfilm"><integer name="width" value="{}"/><integer name="height" value="{}"/><rfilter type="box"/></film>
  </sensor>
  <bsdf type="diffuse" id="white"><rgb name="reflectance" value="0.7, 0.7, 0.7"/></bsdf>
  <bsdf type="diffuse" id="red"><rgb name="reflectance" value="0.7, 0.1, 0.1"/></bsdf>
  <shape type="rectangle"><transform name="to_world"><rotate x="1" angle="-90"/></transform><ref id="white"/></shape>
  <shape type="rectangle"><transform name="to_world"><rotate x="1" angle="90"/><translate y="2"/></transform><ref id="white"/></shape>
  <shape type="rectangle"><transform name="to_world"><translate y="1" z="-1"/></transform><ref id="white"/></shape>
  <shape type="rectangle"><transform name="to_world"><rotate y="1" angle="90"/><translate x="-1" y="1"/></transform><ref id="red"/></shape>
  <shape type="rectangle"><transform name="to_world"><rotate y="1" angle="-90"/><translate x="1" y="1"/></transform><ref id="white"/></shape>
  <shape type="sphere"><point name="center" x="0.3" y="0.35" z="-0.2"/><float name="radius" value="0.35"/><ref id="white"/></shape>
  {}
</scene>)",
                     integrator, sensor, spp, seed, kSize, kSize, light);
}

}  // namespace objektiv::test
