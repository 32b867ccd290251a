#include "optics/film_splat.h"

#include <algorithm>
#include <utility>
#include <vector>

namespace objektiv {

namespace {

// The part of triangle abc inside the unit pixel [x, x + 1] x [y, y + 1] (pixel coordinates):
// the triangle clipped by the pixel's four edges in turn (Sutherland-Hodgman), then its area
// and centroid by the shoelace formulas.
struct Overlap {
  double area = 0;
  Vec2d centroid{0, 0};
};
Overlap OverlapOf(const Vec2d& a, const Vec2d& b, const Vec2d& c, int x, int y) {
  Vec2d buffer[2][9];
  int count = 3;
  buffer[0][0] = a, buffer[0][1] = b, buffer[0][2] = c;
  int from = 0;
  for (int side = 0; side < 4 && count > 0; ++side) {
    // Inside: x >= X0, x <= X1, y >= Y0, y <= Y1 in turn.
    auto value = [&](const Vec2d& p) {
      switch (side) {
        case 0: return p.x - x;
        case 1: return x + 1 - p.x;
        case 2: return p.y - y;
        default: return y + 1 - p.y;
      }
    };
    const Vec2d* in = buffer[from];
    Vec2d* out = buffer[1 - from];
    int n = 0;
    for (int i = 0; i < count; ++i) {
      const Vec2d& p = in[i];
      const Vec2d& q = in[(i + 1) % count];
      const double vp = value(p), vq = value(q);
      if (vp >= 0) out[n++] = p;
      if ((vp >= 0) != (vq >= 0)) out[n++] = p + (q - p) * (vp / (vp - vq));
    }
    count = n;
    from = 1 - from;
  }
  double twice = 0, mx = 0, my = 0;
  const Vec2d* poly = buffer[from];
  for (int i = 0; i < count; ++i) {
    const Vec2d& p = poly[i];
    const Vec2d& q = poly[(i + 1) % count];
    const double cross = p.x * q.y - q.x * p.y;
    twice += cross;
    mx += (p.x + q.x) * cross, my += (p.y + q.y) * cross;
  }
  Overlap o;
  o.area = 0.5 * std::abs(twice);
  o.centroid = twice != 0 ? Vec2d(mx / (3 * twice), my / (3 * twice)) : Vec2d(x + 0.5, y + 0.5);
  return o;
}

// The exact area coverage of a polygon by accumulation (as font rasterisers do it): each edge
// p -> q adds, row by row, the signed area it sweeps to its right into the cells it crosses,
// so that the running sum along a row is the covered share of each pixel (its sign the
// polygon's orientation). `acc` has rows of `width` cells, the polygon within x in [0,
// width - 1); only rows [0, rows) are kept (the polygon may reach beyond them). `spans`, per
// row, the first and the last cell written so far by edges going down and by edges going up
// (widened here): a row's sum is 0 outside them, and constant between the two when they do
// not meet (a convex polygon's inside, where its two sides' cells are apart).
struct RowSpans {
  int lo[2], hi[2];  // [0]: edges with increasing y, [1]: decreasing
};
void AccumulateEdge(Vec2d p, Vec2d q, int width, int rows, double* acc, RowSpans* spans) {
  if (p.y == q.y) return;
  double direction = 1;
  if (p.y > q.y) {
    std::swap(p, q);
    direction = -1;
  }
  // x along the edge at height h, as a share of its height: always between p.x and q.x, even
  // for an edge so flat that its slope dx/dy overflows (rounding past the polygon's columns
  // wrote outside `acc`: a lamp on the axis focuses ghosts into such slivers).
  const double dy = q.y - p.y;
  auto x_at = [&](double h) { return p.x + (q.x - p.x) * std::clamp((h - p.y) / dy, 0.0, 1.0); };
  // Only the rows kept (each row's sums stand alone): x where the edge enters each row anew.
  const int first = std::max(int(std::floor(p.y)), 0), last = std::min(int(std::ceil(q.y)), rows);
  for (int y = first; y < last; ++y) {
    double* line = acc + size_t(y) * width;
    const double top = std::max(double(y), p.y), bottom = std::min(double(y + 1), q.y);
    const double x = x_at(top), x_next = x_at(bottom);
    const double d = (bottom - top) * direction;
    const double lo = std::min(x, x_next), hi = std::max(x, x_next);
    const double lo_floor = std::floor(lo);
    const int i0 = int(lo_floor), i1 = int(std::ceil(hi));
    const int side = direction > 0 ? 0 : 1;
    spans[y].lo[side] = std::min(spans[y].lo[side], i0);
    spans[y].hi[side] = std::max(spans[y].hi[side], std::max(i1, i0 + 1));
    if (i1 <= i0 + 1) {
      // Within one column: the part of the cell right of the segment's mean x.
      const double mean = 0.5 * (x + x_next) - lo_floor;
      line[i0] += d - d * mean;
      line[i0 + 1] += d * mean;
    } else {
      // Across columns: the swept area grows quadratically in the first and the last column,
      // linearly between.
      const double s = 1 / (hi - lo);
      const double lo_frac = lo - lo_floor;
      const double a0 = 0.5 * s * (1 - lo_frac) * (1 - lo_frac);
      const double hi_frac = hi - i1 + 1;
      const double am = 0.5 * s * hi_frac * hi_frac;
      line[i0] += d * a0;
      if (i1 == i0 + 2) {
        line[i0 + 1] += d * (1 - a0 - am);
      } else {
        const double a1 = s * (1.5 - lo_frac);
        line[i0 + 1] += d * (a1 - a0);
        for (int i = i0 + 2; i < i1 - 1; ++i) line[i] += d * s;
        const double a2 = a1 + (i1 - i0 - 3) * s;
        line[i1 - 1] += d * (1 - a2 - am);
      }
      line[i1] += d * am;
    }
  }
}

}  // namespace

double FluxWithin(std::span<const FilmTriangle> triangles, Vec2d lo, Vec2d hi) {
  const double w = hi.x - lo.x, h = hi.y - lo.y;
  if (!(w > 0 && h > 0)) return 0;
  double flux = 0;
  for (const FilmTriangle& t : triangles) {
    // In units of the rectangle, which is then the unit square: its share is the overlap's area
    // over its own.
    auto unit = [&](const Vec2d& p) { return Vec2d((p.x - lo.x) / w, (p.y - lo.y) / h); };
    const Vec2d a = unit(t.a), b = unit(t.b), c = unit(t.c);
    const double area = 0.5 * std::abs((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y));
    if (area > 0) {
      flux += t.flux * std::min(1.0, OverlapOf(a, b, c, 0, 0).area / area);
    } else {  // a degenerate triangle (an edge cell's segment or point): where its middle is
      const Vec2d m = (a + b + c) * (1.0 / 3);
      if (m.x >= 0 && m.x <= 1 && m.y >= 0 && m.y <= 1) flux += t.flux;
    }
  }
  return flux;
}

namespace {

// The rasterisation of Splat: add_at(triangle, pixel index, irradiance) for every pixel a
// triangle covers.
template <class Add>
void Rasterise(std::span<const FilmTriangle> triangles, const FilmRaster& r, double weight, bool pixel_centres,
               Add&& add_at) {
  const double pixel_area = r.w * r.h;
  const FilmTriangle* current = nullptr;
  auto add = [&](int x, int y, double v) {
    if (x >= 0 && y >= 0 && x < r.width && y < r.height) add_at(*current, size_t(y) * r.width + x, v);
  };
  std::vector<double> coverage;
  std::vector<RowSpans> spans;
  // A band of rows (render/lens_flare.cpp) meets few of a bundle's triangles: the rows first.
  const double inv_w = 1 / r.w, inv_h = 1 / r.h;
  for (const FilmTriangle& t : triangles) {
    // Pixel coordinates.
    const double ay = (t.a.y - r.y0) * inv_h, by = (t.b.y - r.y0) * inv_h, cy = (t.c.y - r.y0) * inv_h;
    const double lo_y = std::min({ay, by, cy}), hi_y = std::max({ay, by, cy});
    if (!(hi_y >= 0 && lo_y < r.height)) continue;  // off the rows (or NaN)
    const Vec2d a((t.a.x - r.x0) * inv_w, ay), b((t.b.x - r.x0) * inv_w, by), c((t.c.x - r.x0) * inv_w, cy);
    const double lo_x = std::min({a.x, b.x, c.x}), hi_x = std::max({a.x, b.x, c.x});
    if (!(hi_x >= 0 && lo_x < r.width)) continue;  // off the film (or NaN)
    current = &t;
    const double area = t.Area() / pixel_area;  // in pixels
    // The pixel range it spans, clamped to just outside the image before it becomes an int.
    auto pixel = [](double v, int size) { return int(std::floor(std::clamp(v, -1.0, double(size)))); };
    const int x0 = pixel(lo_x, r.width), x1 = pixel(hi_x, r.width), y0 = pixel(lo_y, r.height), y1 = pixel(hi_y, r.height);
    // Within one pixel, or too thin to clip reliably: all of it there.
    if ((x0 == x1 && y0 == y1) || area < 1e-9) {
      const Vec2d m = (a + b + c) * (1.0 / 3);
      add(pixel(m.x, r.width), pixel(m.y, r.height), weight * t.flux / pixel_area);
      continue;
    }
    const double per_area = weight * t.flux / (area * pixel_area);
    // A varying irradiance: its relative value at a point (barycentric interpolation of the
    // corners' values over their mean, which the triangle's flux fixes), taken at the
    // centroid of the part of the triangle in a pixel (where a linear function has its mean).
    const double mean_e = (t.ea + t.eb + t.ec) / 3;
    const double det = (b.y - c.y) * (a.x - c.x) + (c.x - b.x) * (a.y - c.y);
    // Its change per pixel: where the centroid of a partial pixel's part (within half a pixel
    // of the pixel's centre each way) would change the value by less than kCentroidTolerance,
    // the pixel's centre does (clipping the triangle to the pixel cost half the splat); and
    // uniform where the triangle lies within 2 x 2 pixels (the variation inside one pixel's
    // share of it is below what the pixels resolve: its neighbours carry the bundle's picture).
    constexpr double kCentroidTolerance = 2e-3;
    const double gx = ((t.ea - t.ec) * (b.y - c.y) + (t.eb - t.ec) * (c.y - a.y)) / (det * mean_e);
    const double gy = ((t.ea - t.ec) * (c.x - b.x) + (t.eb - t.ec) * (a.x - c.x)) / (det * mean_e);
    // The relative value is linear: its value at c plus the gradient's share.
    const double at_c = t.ec / mean_e;
    auto relative = [&](Vec2d p) { return std::max(0.0, at_c + gx * (p.x - c.x) + gy * (p.y - c.y)); };
    const double spread = (std::max({t.ea, t.eb, t.ec}) - std::min({t.ea, t.eb, t.ec})) / mean_e;
    const bool uniform = spread < 1e-3 || (x1 - x0 <= 1 && y1 - y0 <= 1);
    const bool centres = pixel_centres || 0.5 * (std::abs(gx) + std::abs(gy)) < kCentroidTolerance;
    // The value of pixel (x, y) given the share of it the triangle covers.
    auto value = [&](int x, int y, double share) {
      if (uniform) return per_area * share;
      const Vec2d centre =
          share >= 1 - 1e-9 || centres ? Vec2d(x + 0.5, y + 0.5) : OverlapOf(a, b, c, x, y).centroid;
      return per_area * share * relative(centre);
    };
    // The exact coverage by accumulated edges, for the rows inside the image (a band of rows:
    // render/lens_flare.cpp splats by bands) and the columns inside it: the parts of the
    // triangle left of the image are pressed onto its left edge, those right of it onto its
    // right edge (each edge cut where it crosses them, then x clamped), which changes the
    // winding number of no point inside the image, so no pixel's coverage.
    const int cx0 = std::max(x0, 0), cx1 = std::min(x1, r.width - 1);
    // Columns: the pixels', then two for what the edges at the right end write past them.
    const int cols = cx1 - cx0 + 1, bw = cols + 2;
    const int row0 = std::max(y0, 0), bh = std::min(y1, r.height - 1) - row0 + 1;
    coverage.assign(size_t(bw) * bh, 0.0);
    spans.assign(size_t(bh), RowSpans{{bw, bw}, {-1, -1}});
    const Vec2d o(cx0, row0);
    const double left = 0 - cx0, right = r.width - cx0;  // the image's edges, in the buffer's columns
    for (const auto& edge : {std::pair{a - o, b - o}, {b - o, c - o}, {c - o, a - o}}) {
      const Vec2d p = edge.first, q = edge.second;  // (clang 14: no lambda captures a structured binding)
      double cuts[4] = {0, 1, 1, 1};
      int n = 1;
      for (const double bound : {left, right})
        if ((p.x - bound) * (q.x - bound) < 0) cuts[n++] = (bound - p.x) / (q.x - p.x);
      if (n == 3 && cuts[2] < cuts[1]) std::swap(cuts[1], cuts[2]);
      cuts[n] = 1;
      auto at = [&](double u) {
        const Vec2d v = u >= 1 ? q : p + (q - p) * u;
        return Vec2d(std::clamp(v.x, left, right), v.y);
      };
      for (int k = 0; k < n; ++k) AccumulateEdge(at(cuts[k]), at(cuts[k + 1]), bw, bh, coverage.data(), spans.data());
    }
    // The value along a row where the share is constant and the irradiance taken at pixel
    // centres: linear in x.
    const bool linear_inside = uniform || centres;
    for (int y = 0; y < bh; ++y) {
      const RowSpans& sp = spans[y];
      const int first = std::min(sp.lo[0], sp.lo[1]), last = std::min(std::max(sp.hi[0], sp.hi[1]), cols - 1);
      // The cells between the two sides' (none written: the share constant).
      int gap_lo = last + 1, gap_hi = last;
      if (sp.hi[0] < sp.lo[1]) {
        gap_lo = sp.hi[0] + 1, gap_hi = std::min(sp.lo[1] - 1, last);
      } else if (sp.hi[1] < sp.lo[0]) {
        gap_lo = sp.hi[1] + 1, gap_hi = std::min(sp.lo[0] - 1, last);
      }
      double sum = 0;
      const double* row = &coverage[size_t(y) * bw];
      const size_t start = size_t(row0 + y) * r.width + cx0;
      auto each_cell = [&](int from, int to) {
        for (int x = from; x <= to; ++x) {
          sum += row[x];
          const double share = std::min(std::abs(sum), 1.0);
          if (share > 1e-12) add_at(t, start + x, value(cx0 + x, row0 + y, share));
        }
      };
      each_cell(first, gap_lo - 1);
      if (gap_lo <= gap_hi) {
        const double share = std::min(std::abs(sum), 1.0);
        if (share > 1e-12 && (linear_inside || share >= 1 - 1e-9)) {
          const double py = row0 + y + 0.5 - c.y;
          double rel = at_c + gx * (cx0 + gap_lo + 0.5 - c.x) + gy * py;
          const double scale = per_area * share;
          for (int x = gap_lo; x <= gap_hi; ++x, rel += gx) add_at(t, start + x, uniform ? scale : scale * std::max(0.0, rel));
        } else if (share > 1e-12) {
          for (int x = gap_lo; x <= gap_hi; ++x) add_at(t, start + x, value(cx0 + x, row0 + y, share));
        }
      }
      each_cell(std::max(gap_hi + 1, gap_lo), last);
    }
  }
}

}  // namespace

void Splat(std::span<const FilmTriangle> triangles, const FilmRaster& r, double weight, float* image, int stride) {
  Rasterise(triangles, r, weight, false, [&](const FilmTriangle&, size_t i, double v) { image[i * stride] += float(v); });
}

FilmRaster HalfResolution(const FilmRaster& r) {
  FilmRaster half = r;
  half.width = (r.width + 1) / 2, half.height = (r.height + 1) / 2;
  half.w = 2 * r.w, half.h = 2 * r.h;
  return half;
}

double IrradianceContrast(std::span<const FilmTriangle> triangles) {
  double flux = 0, area = 0, flux_times_irradiance = 0;
  for (const FilmTriangle& t : triangles) area += t.Area();
  if (triangles.empty() || !(area > 0)) return 1;
  const double smallest = 1e-3 * area / double(triangles.size());
  double largest = 0;
  for (const FilmTriangle& t : triangles) {
    const double a = t.Area();
    if (a < smallest || !(t.flux > 0)) continue;
    const double e = t.flux / a * std::max({t.ea, t.eb, t.ec}) / ((t.ea + t.eb + t.ec) / 3);
    largest = std::max(largest, e);
    flux += t.flux, flux_times_irradiance += t.flux * t.flux / a;
  }
  return flux > 0 ? largest / (flux_times_irradiance / flux) : 1;
}

void AddUpsampled(const float* half, int width, int height, int y0, int y1, float* full) {
  const int hw = (width + 1) / 2, hh = (height + 1) / 2;
  // Full pixel 2i sits at half coordinate i - 1/4, 2i + 1 at i + 1/4: 3/4 of half pixel i and
  // 1/4 of its neighbour on that side.
  auto neighbour = [](int full_index, int size) {
    const int i = full_index / 2;
    return std::clamp(full_index % 2 ? i + 1 : i - 1, 0, size - 1);
  };
  for (int y = y0; y < y1; ++y) {
    const float* row_a = half + size_t(y / 2) * hw * 3;
    const float* row_b = half + size_t(neighbour(y, hh)) * hw * 3;
    float* out = full + size_t(y) * width * 3;
    for (int x = 0; x < width; ++x) {
      const size_t i = size_t(x / 2) * 3, j = size_t(neighbour(x, hw)) * 3;
      for (int c = 0; c < 3; ++c)
        out[3 * x + c] += 0.5625f * row_a[i + c] + 0.1875f * (row_a[j + c] + row_b[i + c]) + 0.0625f * row_b[j + c];
    }
  }
}

void SplatColour(std::span<const FilmTriangle> triangles, const FilmRaster& r, const Vec3d& weight, float* xyz,
                 bool pixel_centres) {
  Rasterise(triangles, r, 1.0, pixel_centres, [&](const FilmTriangle&, size_t i, double v) {
    float* p = xyz + 3 * i;
    p[0] += float(weight.x * v), p[1] += float(weight.y * v), p[2] += float(weight.z * v);
  });
}

void SplatTinted(std::span<const FilmTriangle> triangles, const FilmRaster& r, float* xyz, bool pixel_centres) {
  Rasterise(triangles, r, 1.0, pixel_centres, [&](const FilmTriangle& t, size_t i, double v) {
    float* p = xyz + 3 * i;
    p[0] += float(t.tint.x * v), p[1] += float(t.tint.y * v), p[2] += float(t.tint.z * v);
  });
}

}  // namespace objektiv
