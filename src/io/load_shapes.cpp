// Builders for <shape>: meshes from files, analytic shapes, their BSDFs and area emitters.
#include <functional>

#include "io/loader_context.h"
#include "io/mesh_io.h"
#include "scene/analytic_shape.h"

namespace objektiv {
namespace {

using ShapeList = std::vector<std::unique_ptr<Shape>>;
using ShapeFactory = std::function<ShapeList(const Properties&)>;

MeshLoadOptions MeshOptions(const Properties& p, bool is_obj) {
  MeshLoadOptions o;
  if (is_obj) {
    o.group = p.String("group", "");
    o.flip_tex_coords = p.Bool("flip_tex_coords", true);
  }
  o.face_normals = p.Bool("face_normals", false);
  return o;
}

ShapeList One(std::unique_ptr<Shape> s) {
  ShapeList l;
  l.push_back(std::move(s));
  return l;
}

// Mitsuba's cylinder from p0 to p1 with a radius: the unit cylinder placed along p1 - p0.
Transform CylinderFrame(const Vec3d& p0, const Vec3d& p1, double radius, const Location& loc) {
  Vec3d axis = p1 - p0;
  double len = Length(axis);
  if (!(len > 0)) throw ErrorAt(loc, "cylinder: p0 and p1 coincide");
  if (!(radius > 0)) throw ErrorAt(loc, "cylinder: radius must be positive");
  Frame f = Frame::FromZ(Vec3f(axis / len));
  Matrix4 m = Matrix4::Identity();
  for (int i = 0; i < 3; ++i) {
    m.m[i][0] = f.s[i] * radius;
    m.m[i][1] = f.t[i] * radius;
    m.m[i][2] = axis[i];
    m.m[i][3] = p0[i];
  }
  return Transform(m);
}

const std::map<std::string, ShapeFactory>& ShapeRegistry() {
  static const std::map<std::string, ShapeFactory> registry = {
      {"obj",
       [](const Properties& p) {
         MeshData m = LoadObj(ResolvePath(p.LocOf("filename"), p.String("filename")), MeshOptions(p, true));
         return One(std::make_unique<TriangleMesh>(std::move(m), p.GetTransform("to_world"), p.Bool("flip_normals", false)));
       }},
      {"ply",
       [](const Properties& p) {
         MeshData m = LoadPly(ResolvePath(p.LocOf("filename"), p.String("filename")), MeshOptions(p, false));
         return One(std::make_unique<TriangleMesh>(std::move(m), p.GetTransform("to_world"), p.Bool("flip_normals", false)));
       }},
      {"rectangle",
       [](const Properties& p) {
         return One(std::make_unique<TriangleMesh>(TriangleMesh::Rectangle(), p.GetTransform("to_world"),
                                                   p.Bool("flip_normals", false)));
       }},
      {"cube",
       [](const Properties& p) {
         return One(std::make_unique<TriangleMesh>(TriangleMesh::Cube(), p.GetTransform("to_world"),
                                                   p.Bool("flip_normals", false)));
       }},
      {"sphere",
       [](const Properties& p) {
         double r = p.Float("radius", 1);
         if (!(r > 0)) throw ErrorAt(p.LocOf("radius"), "sphere radius must be positive");
         return One(std::make_unique<Sphere>(Vec3f(p.Point("center", Vec3d(0.0))), float(r), p.Bool("flip_normals", false),
                                             p.GetTransform("to_world")));
       }},
      {"disk",
       [](const Properties& p) {
         return One(std::make_unique<Disk>(p.GetTransform("to_world"), p.Bool("flip_normals", false)));
       }},
      {"cylinder",
       [](const Properties& p) {
         Transform to_world = p.GetTransform("to_world");
         Transform frame = CylinderFrame(p.Point("p0", Vec3d(0, 0, 0)), p.Point("p1", Vec3d(0, 0, 1)),
                                         p.Float("radius", 1), p.loc());
         bool flip = p.Bool("flip_normals", false);
         ShapeList l = One(std::make_unique<Cylinder>(to_world * frame, flip));
         // Objektiv extension: caps close the cylinder with two disks facing outwards.
         if (p.Bool("caps", false)) {
           l.push_back(std::make_unique<Disk>(to_world * frame * Transform::Rotate(180, {1, 0, 0}), flip));
           l.push_back(std::make_unique<Disk>(to_world * frame * Transform::Translate({0, 0, 1}), flip));
         }
         return l;
       }},
      {"plane",
       [](const Properties& p) {
         return One(std::make_unique<InfinitePlane>(p.GetTransform("to_world"), p.Bool("flip_normals", false)));
       }},
  };
  return registry;
}

}  // namespace

namespace {

int BuildShapeGroup(const ObjectNode& node, LoaderContext& ctx) {
  if (auto it = ctx.shape_groups.find(&node); it != ctx.shape_groups.end()) return it->second;
  Properties props(node);
  int group = ctx.scene.AddShapeGroup();
  ctx.shape_groups[&node] = group;
  auto shapes = props.Children("shape");
  if (shapes.empty()) throw ErrorAt(node.loc, "a shapegroup needs at least one nested <shape>");
  for (const auto& child : shapes) {
    if (child->type == "shapegroup" || child->type == "instance")
      throw ErrorAt(child->loc, "a shapegroup cannot contain a {} (one level of instancing)", child->type);
    BuildShape(*child, ctx, group);
  }
  props.WarnUnused();
  return group;
}

void BuildInstance(const ObjectNode& node, LoaderContext& ctx) {
  Properties props(node);
  auto refs = props.Children("shape");
  if (refs.size() != 1 || refs[0]->type != "shapegroup")
    throw ErrorAt(node.loc, "an instance needs exactly one <ref> to a shapegroup");
  int group = BuildShapeGroup(*refs[0], ctx);
  try {
    ctx.scene.AddInstance(group, props.GetTransform("to_world"));
  } catch (const std::invalid_argument& e) {
    throw ErrorAt(node.loc, "{}", e.what());
  }
  props.WarnUnused();
}

}  // namespace

void BuildShape(const ObjectNode& node, LoaderContext& ctx, int group) {
  if (node.type == "shapegroup") {
    if (group >= 0) throw ErrorAt(node.loc, "shapegroups cannot be nested");
    BuildShapeGroup(node, ctx);
    return;
  }
  if (node.type == "instance") {
    BuildInstance(node, ctx);
    return;
  }
  const auto& registry = ShapeRegistry();
  auto it = registry.find(node.type);
  if (it == registry.end()) UnknownType(node, registry);
  Properties props(node);
  ShapeList shapes;
  try {
    shapes = it->second(props);
  } catch (const std::invalid_argument& e) {
    throw ErrorAt(node.loc, "{}", e.what());
  }
  // The BSDF: one nested or referenced <bsdf> (named or not), by default Mitsuba's diffuse 0.5.
  std::shared_ptr<const Material> material;
  auto bsdfs = props.Children("bsdf");
  if (bsdfs.size() > 1) throw ErrorAt(bsdfs[1]->loc, "a shape takes one <bsdf>");
  if (!bsdfs.empty()) {
    material = BuildMaterial(*bsdfs[0], ctx);
  } else {
    static const auto default_material = std::make_shared<DiffuseMaterial>(std::make_shared<ConstantTexture>(Spectrum(0.5f)));
    material = default_material;
  }
  auto emitters = props.Children("emitter");
  if (emitters.size() > 1) throw ErrorAt(emitters[1]->loc, "a shape takes one <emitter>");
  std::shared_ptr<const SpectrumTexture> radiance;
  bool two_sided = false;
  if (!emitters.empty()) {
    const ObjectNode& e = *emitters[0];
    if (e.type != "area") throw ErrorAt(e.loc, "an emitter inside a shape must be of type 'area', not '{}'", e.type);
    Properties ep(e);
    radiance = GetTexture(ep, "radiance", SpectrumUsage::kIlluminant, 1, ctx);
    two_sided = ep.Bool("two_sided", false);
    ep.WarnUnused();
  }
  if (group >= 0) {
    if (radiance) throw ErrorAt(emitters[0]->loc, "shapes inside a shapegroup cannot emit light");
    // An instance's bounds are its group's, transformed: the plane's would leave Embree's range.
    if (node.type == "plane") throw ErrorAt(node.loc, "an infinite plane cannot be part of a shapegroup");
    for (auto& shape : shapes) ctx.scene.AddShapeToGroup(group, std::move(shape), material);
    props.WarnUnused();
    return;
  }
  for (auto& shape : shapes) {
    if (radiance && !(shape->Area() < std::numeric_limits<float>::infinity()))
      throw ErrorAt(node.loc, "an infinite plane cannot be an area emitter");
    if (radiance && !(shape->Area() > 0)) throw ErrorAt(node.loc, "an area emitter needs a shape with positive area");
    ShapeRecord& rec = ctx.scene.AddShape(std::move(shape), material);
    if (radiance) ctx.scene.AddAreaLight(rec, radiance, two_sided);
  }
  props.WarnUnused();
}

}  // namespace objektiv
