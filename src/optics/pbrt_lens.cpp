#include "optics/pbrt_lens.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "base/error.h"
#include "base/log.h"
#include "base/text_file.h"

namespace objektiv {

LensPrescription ReadPbrtLens(const std::string& path) { return ParsePbrtLens(ReadTextFile(path, "lens file"), path); }

LensPrescription ParsePbrtLens(const std::string& text, const std::string& path) {
  LensPrescription lens;
  lens.name = std::filesystem::path(path).stem().string();
  lens.source = path;
  lens.file = path;
  std::istringstream lines(text);
  std::string line;
  int number = 0, stop_line = 0;
  std::vector<int> rows;  // each surface's line
  // Media are shared between rows with the same index.
  std::map<double, std::shared_ptr<const Glass>> media;
  bool described = false;
  double index_before = 1;  // the medium in front of the current row (air before the first)
  while (std::getline(lines, line)) {
    ++number;
    size_t hash = line.find('#');
    if (hash != std::string::npos) {
      // The first comment line names the design (pbrt's files start with one).
      if (!described) {
        std::string c = line.substr(hash + 1);
        while (!c.empty() && (c.back() == '\t' || c.back() == ' ' || c.back() == '"' || c.back() == '\r')) c.pop_back();
        size_t b = c.find_first_not_of(" \t");
        if (b != std::string::npos) {
          lens.source = c.substr(b);
          described = true;
        }
      }
      line.resize(hash);
    }
    std::vector<double> v;
    for (const std::string& t : SplitFields(line)) v.push_back(ParseFiniteNumber(t, path, number));
    if (v.empty()) continue;
    if (v.size() != 4)
      throw MakeInputError(path, number, "a lens row needs 4 numbers (radius, thickness, index, aperture), got {}", v.size());
    LensSurface s;
    s.radius = v[0];
    s.thickness = v[1];
    s.semi_diameter = v[3] / 2;
    if (v[3] <= 0) throw MakeInputError(path, number, "aperture diameter must be positive, got {}", v[3]);
    if (s.thickness < 0) throw MakeInputError(path, number, "thickness must not be negative, got {}", s.thickness);
    if (v[2] != 0 && v[2] < 1) throw MakeInputError(path, number, "index of refraction {} is below 1", v[2]);
    double n = (v[2] == 0) ? 1 : v[2];
    if (v[0] == 0) {
      if (stop_line) throw MakeInputError(path, number, "a second aperture stop (radius 0; the first is on line {})", stop_line);
      s.is_stop = true;
      stop_line = number;
      // The index is the medium after the stop, which may lie inside glass. Where it differs
      // from the medium before, the stop's plane is also a flat interface between them.
      if (n != index_before)
        spdlog::warn("{}:{}: the stop row's index {} differs from the medium before it ({}); pbrt-v4 does not "
                     "refract there, Objektiv refracts at the stop's plane as at any flat interface",
                     path, number, n, index_before);
    } else if (s.semi_diameter > std::abs(s.radius)) {
      throw MakeInputError(path, number, "semi-diameter {} is larger than the radius {}", s.semi_diameter, s.radius);
    }
    CheckSize(s, path, number);
    index_before = n;
    if (n != 1) {
      auto& m = media[n];
      if (!m) m = std::make_shared<const Glass>(Glass::Constant(n));
      s.medium = m;
    }
    lens.surfaces.push_back(std::move(s));
    rows.push_back(number);
  }
  if (lens.surfaces.empty()) throw MakeInputError(path, 0, "no lens surfaces");
  if (!stop_line) throw MakeInputError(path, 0, "no aperture stop (a row with radius 0)");
  if (lens.surfaces.back().medium) throw MakeInputError(path, number, "the last surface must leave the lens into air");
  if (auto crossed = FirstCrossedGap(lens)) throw MakeInputError(path, rows[crossed->first], "{}", crossed->second);
  return lens;
}

}  // namespace objektiv
