// The <shape> plugins: meshes from files and analytic shapes (with their BSDFs and area
// emitters), shape groups and their instances.
#include <spdlog/spdlog.h>

#include "io/loader_context.h"
#include "io/mesh_io.h"
#include "scene/analytic_shape.h"

namespace objektiv {
namespace {

using ShapeList = std::vector<std::unique_ptr<Shape>>;
using ShapePlugin = ShapeRegistry::PluginType;

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

// What every shape that makes surfaces reads (shapegroup and instance do not).
const std::vector<PropertyDecl> kSurfaceProperties = {{"to_world", PropType::kTransform},
                                                      {"flip_normals", PropType::kBoolean},
                                                      {"bsdf", PropType::kObject},
                                                      {"emitter", PropType::kObject},
                                                      {"interior", PropType::kMedium},
                                                      {"exterior", PropType::kMedium}};

// Adds the surfaces a shape made to the scene (group < 0) or to a shape group, with the
// shape's BSDF and area emitter.
void AddSurfaces(const Properties& props, ShapeList shapes, LoaderContext& ctx, int group) {
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
  Emission emission;
  if (!emitters.empty()) {
    const ObjectNode& e = *emitters[0];
    if (e.type != "area") throw ErrorAt(e.loc, "an emitter inside a shape must be of type 'area', not '{}'", e.type);
    emission = EmitterPlugins().Build(e, ctx);
  }
  const auto& radiance = emission.area_radiance;
  // Light sampling picks points over the whole surface; rays would pass a mask's holes.
  if (radiance && material->HasOpacity())
    throw ErrorAt(emitters[0]->loc, "an area emitter cannot be on a shape whose BSDF is a mask (or holds one)");
  if (radiance && material->IsNull())
    throw ErrorAt(emitters[0]->loc, "a shape with a null BSDF (a medium boundary) cannot emit light");
  // The media on its two sides (ShapeRecord::interior, exterior).
  const Medium* interior = MediumProperty(props, "interior", ctx);
  const Medium* exterior = MediumProperty(props, "exterior", ctx);
  const bool medium_interface = props.Has("interior") || props.Has("exterior");
  // Rays through a mask's holes pass the surface as if it were not there: they would not enter
  // or leave the medium it bounds.
  if (medium_interface && material->HasOpacity())
    throw ErrorAt(props.LocOf(props.Has("interior") ? "interior" : "exterior"),
                  "a shape that bounds a medium cannot have a mask BSDF (rays through its holes would not enter the "
                  "medium): bound the medium by a null or a closed surface of its own");
  if (interior && !material->MayTransmit())
    spdlog::warn("{}:{}: this shape's interior medium is never entered: its BSDF lets no light through (a medium "
                 "inside glass needs a dielectric, roughdielectric, thindielectric, principled with spec_trans, or null)",
                 props.LocOf("interior").file, props.LocOf("interior").line);
  if (group >= 0) {
    if (medium_interface)
      throw ErrorAt(props.LocOf(props.Has("interior") ? "interior" : "exterior"),
                    "shapes inside a shapegroup cannot bound media");
    if (radiance) throw ErrorAt(emitters[0]->loc, "shapes inside a shapegroup cannot emit light");
    // An instance's bounds are its group's, transformed: the plane's would leave Embree's range.
    if (props.type() == "plane") throw ErrorAt(props.loc(), "an infinite plane cannot be part of a shapegroup");
    for (auto& shape : shapes) ctx.scene.AddShapeToGroup(group, std::move(shape), material);
    return;
  }
  for (auto& shape : shapes) {
    if (radiance && !(shape->Area() < std::numeric_limits<float>::infinity()))
      throw ErrorAt(props.loc(), "an infinite plane cannot be an area emitter");
    if (radiance && !(shape->Area() > 0))
      throw ErrorAt(props.loc(), "an area emitter needs a shape with positive area");
    ShapeRecord& rec = ctx.scene.AddShape(std::move(shape), material);
    rec.interior = interior;
    rec.exterior = exterior;
    rec.medium_interface = medium_interface;
    if (radiance) ctx.scene.AddAreaLight(rec, radiance, emission.two_sided);
  }
}

// A plugin whose `make` makes surfaces from its own properties; they get the shape's BSDF
// and area emitter.
ShapePlugin Surfaces(const char* type, const std::vector<PropertyDecl>& own, ShapeList (*make)(const Properties&)) {
  return {type, Join(kSurfaceProperties, own), [make](const Properties& p, LoaderContext& ctx, int group) {
            ShapeList shapes;
            try {
              shapes = make(p);
            } catch (const std::invalid_argument& e) {
              throw ErrorAt(p.loc(), "{}", e.what());
            }
            AddSurfaces(p, std::move(shapes), ctx, group);
            return -1;
          }};
}

ShapeList Mesh(MeshData m, const Properties& p) {
  return One(std::make_unique<TriangleMesh>(std::move(m), p.GetTransform("to_world"), p.Bool("flip_normals", false)));
}

ShapeList MakeObj(const Properties& p) {
  return Mesh(LoadObj(ResolvePath(p.LocOf("filename"), p.String("filename")), MeshOptions(p, true)), p);
}

ShapeList MakePly(const Properties& p) {
  return Mesh(LoadPly(ResolvePath(p.LocOf("filename"), p.String("filename")), MeshOptions(p, false)), p);
}

ShapeList MakeSphere(const Properties& p) {
  double r = p.Float("radius", 1);
  if (!(r > 0)) throw ErrorAt(p.LocOf("radius"), "sphere radius must be positive");
  return One(std::make_unique<Sphere>(Vec3f(p.Point("center", Vec3d(0.0))), float(r), p.Bool("flip_normals", false),
                                      p.GetTransform("to_world")));
}

ShapeList MakeCylinder(const Properties& p) {
  Transform to_world = p.GetTransform("to_world");
  Transform frame =
      CylinderFrame(p.Point("p0", Vec3d(0, 0, 0)), p.Point("p1", Vec3d(0, 0, 1)), p.Float("radius", 1), p.loc());
  bool flip = p.Bool("flip_normals", false);
  ShapeList l = One(std::make_unique<Cylinder>(to_world * frame, flip));
  // Objektiv extension: caps close the cylinder with two disks facing outwards.
  if (p.Bool("caps", false)) {
    l.push_back(std::make_unique<Disk>(to_world * frame * Transform::Rotate(180, {1, 0, 0}), flip));
    l.push_back(std::make_unique<Disk>(to_world * frame * Transform::Translate({0, 0, 1}), flip));
  }
  return l;
}

int BuildShapeGroup(const Properties& props, LoaderContext& ctx, int group) {
  if (group >= 0) throw ErrorAt(props.loc(), "shapegroups cannot be nested");
  int made = ctx.scene.AddShapeGroup();
  auto shapes = props.Children("shape");
  if (shapes.empty()) throw ErrorAt(props.loc(), "a shapegroup needs at least one nested <shape>");
  for (const auto& child : shapes) {
    if (child->type == "shapegroup" || child->type == "instance")
      throw ErrorAt(child->loc, "a shapegroup cannot contain a {} (one level of instancing)", child->type);
    BuildShape(*child, ctx, made);
  }
  return made;
}

int BuildInstance(const Properties& props, LoaderContext& ctx, int) {
  auto refs = props.Children("shape");
  if (refs.size() != 1 || refs[0]->type != "shapegroup")
    throw ErrorAt(props.loc(), "an instance needs exactly one <ref> to a shapegroup");
  int group = BuildShape(*refs[0], ctx);
  try {
    ctx.scene.AddInstance(group, props.GetTransform("to_world"));
  } catch (const std::invalid_argument& e) {
    throw ErrorAt(props.loc(), "{}", e.what());
  }
  return -1;
}

}  // namespace

const ShapeRegistry& ShapePlugins() {
  using P = const Properties&;
  static const ShapeRegistry registry(
      "shape", {},
      {
          Surfaces("obj",
                   {{"filename", PropType::kString},
                    {"face_normals", PropType::kBoolean},
                    {"flip_tex_coords", PropType::kBoolean},
                    {"group", PropType::kString}},
                   MakeObj),
          Surfaces("ply", {{"filename", PropType::kString}, {"face_normals", PropType::kBoolean}}, MakePly),
          Surfaces("rectangle", {}, [](P p) { return Mesh(TriangleMesh::Rectangle(), p); }),
          Surfaces("cube", {}, [](P p) { return Mesh(TriangleMesh::Cube(), p); }),
          Surfaces("sphere", {{"center", PropType::kPoint}, {"radius", PropType::kFloat}}, MakeSphere),
          Surfaces("disk", {},
                   [](P p) {
                     return One(std::make_unique<Disk>(p.GetTransform("to_world"), p.Bool("flip_normals", false)));
                   }),
          Surfaces("cylinder",
                   {{"p0", PropType::kPoint},
                    {"p1", PropType::kPoint},
                    {"radius", PropType::kFloat},
                    {"caps", PropType::kBoolean}},
                   MakeCylinder),
          Surfaces("plane", {},
                   [](P p) {
                     return One(
                         std::make_unique<InfinitePlane>(p.GetTransform("to_world"), p.Bool("flip_normals", false)));
                   }),
          {"shapegroup", {{"shape", PropType::kObject}}, BuildShapeGroup},
          {"instance", {{"to_world", PropType::kTransform}, {"shape", PropType::kObject}}, BuildInstance},
      });
  return registry;
}

int BuildShape(const ObjectNode& node, LoaderContext& ctx, int group) {
  if (auto it = ctx.shape_groups.find(&node); it != ctx.shape_groups.end()) return it->second;
  int made = ShapePlugins().Build(node, ctx, group);
  if (made >= 0) ctx.shape_groups[&node] = made;
  return made;
}

}  // namespace objektiv
