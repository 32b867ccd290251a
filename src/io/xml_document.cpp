#include "io/xml_document.h"

#include "base/log.h"
#include "base/text_file.h"

#include <pugixml.hpp>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string_view>

namespace objektiv {
namespace {

namespace fs = std::filesystem;

struct FileContext {
  std::string path;
  std::vector<size_t> line_starts;  // byte offset of each line

  int LineOf(ptrdiff_t offset) const {
    if (offset < 0) return 0;
    auto it = std::upper_bound(line_starts.begin(), line_starts.end(), size_t(offset));
    return int(it - line_starts.begin());
  }
};

// A pbrt scene file: named .pbrt, or text whose first word (after comments) is a pbrt
// directive rather than an XML tag.
bool LooksLikePbrt(const std::string& text, const std::string& name) {
  std::string ext = fs::path(name).extension().string();
  if (ext == ".pbrt" || ext == ".PBRT") return true;
  size_t i = 0;
  while (i < text.size()) {
    if (std::isspace(static_cast<unsigned char>(text[i]))) {
      ++i;
    } else if (text[i] == '#') {
      while (i < text.size() && text[i] != '\n') ++i;
    } else {
      break;
    }
  }
  size_t j = i;
  while (j < text.size() && std::isalpha(static_cast<unsigned char>(text[j]))) ++j;
  static const std::set<std::string> kDirectives = {
      "LookAt", "Camera", "Film", "Sampler", "Integrator", "PixelFilter", "WorldBegin", "AttributeBegin", "Shape",
      "LightSource", "Material", "MakeNamedMaterial", "Texture", "Translate", "Rotate", "Scale", "Transform",
      "ConcatTransform", "CoordinateSystem", "CoordSysTransform", "Option", "ColorSpace", "Accelerator", "Import",
      "Include", "TransformBegin", "ObjectBegin", "MakeNamedMedium", "ReverseOrientation", "Identity"};
  return kDirectives.count(text.substr(i, j - i)) > 0;
}

class Parser {
 public:
  explicit Parser(std::map<std::string, std::string> defines) : params_(std::move(defines)) {
    for (const auto& [k, v] : params_) overridden_.insert({k, true});
  }

  SceneDocument ParseFile(const std::string& path) { return ParseString(ReadTextFile(path, "scene file"), path); }

  SceneDocument ParseString(const std::string& text, const std::string& name) {
    auto root = std::make_shared<ObjectNode>();
    root->tag = "scene";
    root->used = true;
    pugi::xml_document doc;
    FileContext ctx = Load(text, name, &doc);
    pugi::xml_node scene = doc.child("scene");
    if (!scene) throw MakeInputError(name, 1, "the root element must be <scene>");
    root->loc = {name, ctx.LineOf(scene.offset_debug())};
    CheckAttributes(scene, {"version"}, root->loc);  // Mitsuba 3's version of the language
    Walk(scene, ctx, *root, 0, 0);
    for (const auto& [key, overridden] : overridden_)
      if (!declared_.count(key))
        spdlog::warn("{}: -D {}: the scene declares no parameter '{}' (no <default> and no ${}); ignored", name, key,
                     key, key);
    return SceneDocument{root};
  }

 private:
  FileContext Load(const std::string& text, const std::string& name, pugi::xml_document* doc) {
    if (LooksLikePbrt(text, name))
      throw MakeInputError(name, 0, "a pbrt scene: Objektiv reads scenes only in its XML language (Mitsuba 3's), not "
                                    "in pbrt's format (pbrt's lens files, .dat, it does read)");
    xml_bytes_ += text.size();
    if (xml_bytes_ > kMaxTextFileBytes)
      throw MakeInputError(name, 0, "the scene and its includes hold more than {} MiB of XML in all",
                           kMaxTextFileBytes >> 20);
    FileContext ctx;
    ctx.path = name;
    ctx.line_starts.push_back(0);
    for (size_t i = 0; i < text.size(); ++i)
      if (text[i] == '\n') ctx.line_starts.push_back(i + 1);
    pugi::xml_parse_result r = doc->load_buffer(text.data(), text.size(), pugi::parse_default | pugi::parse_ws_pcdata_single);
    if (!r) throw MakeInputError(name, ctx.LineOf(r.offset), "XML syntax error: {}", r.description());
    WarnAboutIgnoredContent(*doc, ctx);
    return ctx;
  }

  // The language gives everything in elements and attributes: text between the tags, and
  // elements beside the root <scene>, are warned about (pugixml walks the tree without
  // recursion, so a deep document cannot overflow the stack here).
  void WarnAboutIgnoredContent(const pugi::xml_document& doc, const FileContext& ctx) const {
    struct Walker : pugi::xml_tree_walker {
      const FileContext* ctx;
      bool for_each(pugi::xml_node& n) override {
        if (n.type() != pugi::node_pcdata && n.type() != pugi::node_cdata) return true;
        std::string_view text = n.value();
        size_t first = text.find_first_not_of(" \t\r\n");
        if (first == std::string_view::npos) return true;
        std::string_view shown = text.substr(first, 40);
        shown = shown.substr(0, shown.find_first_of("\r\n"));
        const bool cut = text.find_first_not_of(" \t\r\n", first + shown.size()) != std::string_view::npos;
        shown = shown.substr(0, shown.find_last_not_of(" \t") + 1);
        // The line of the text's first character (a node's offset is where its whitespace starts).
        const int line = ctx->LineOf(n.offset_debug() + std::ptrdiff_t(first));
        spdlog::warn("{}:{}: text inside <{}> is ignored: \"{}{}\"", ctx->path, line,
                     n.parent().type() == pugi::node_element ? n.parent().name() : "the document", shown,
                     cut ? "..." : "");
        return true;
      }
    } walker;
    walker.ctx = &ctx;
    const_cast<pugi::xml_document&>(doc).traverse(walker);
    bool root_seen = false;
    for (pugi::xml_node top : doc.children()) {
      if (top.type() != pugi::node_element) continue;
      if (!root_seen && std::string_view(top.name()) == "scene") {
        root_seen = true;
        continue;
      }
      Location loc = Loc(ctx, top);
      spdlog::warn("{}:{}: <{}> beside the root <scene> is ignored", loc.file, loc.line, top.name());
    }
  }

  Location Loc(const FileContext& ctx, const pugi::xml_node& n) const { return {ctx.path, ctx.LineOf(n.offset_debug())}; }

  // Replaces $name (letters, digits, underscore) with its parameter value.
  std::string Substitute(const std::string& s, const Location& loc) const {
    std::string out;
    for (size_t i = 0; i < s.size(); ++i) {
      if (s[i] != '$') {
        out += s[i];
        continue;
      }
      size_t j = i + 1;
      while (j < s.size() && (std::isalnum(static_cast<unsigned char>(s[j])) || s[j] == '_')) ++j;
      std::string key = s.substr(i + 1, j - i - 1);
      if (key.empty()) throw ErrorAt(loc, "'$' not followed by a parameter name in \"{}\"", s);
      declared_.insert(key);
      auto it = params_.find(key);
      if (it == params_.end()) throw ErrorAt(loc, "undefined parameter ${} (define it with <default> or -D)", key);
      // Parameters made of parameters grow exponentially: bound all the text they make.
      substituted_bytes_ += it->second.size();
      if (substituted_bytes_ > kMaxTextFileBytes)
        throw ErrorAt(loc, "parameter substitution has made more than {} MiB of text", kMaxTextFileBytes >> 20);
      out += it->second;
      i = j - 1;
    }
    return out;
  }

  std::string Attr(const pugi::xml_node& n, const char* name, const Location& loc, bool required = true) const {
    pugi::xml_attribute a = n.attribute(name);
    if (!a) {
      if (required) throw ErrorAt(loc, "<{}> needs the attribute '{}'", n.name(), name);
      return {};
    }
    return Substitute(a.value(), loc);
  }

  // Only the listed attributes may appear on n.
  void CheckAttributes(const pugi::xml_node& n, std::initializer_list<const char*> allowed, const Location& loc) const {
    for (pugi::xml_attribute a : n.attributes()) {
      bool ok = false;
      for (const char* name : allowed) ok |= std::string(a.name()) == name;
      if (!ok) throw ErrorAt(loc, "<{}> does not take the attribute '{}'", n.name(), a.name());
    }
  }

  static double ParseDouble(const std::string& s, const Location& loc) {
    std::optional<double> v = ParseFiniteNumber(s);
    if (!v) throw ErrorAt(loc, "'{}' is not a finite number", s);
    return *v;
  }

  static int64_t ParseInt(const std::string& s, const Location& loc) {
    const char* begin = s.c_str();
    char* end = nullptr;
    errno = 0;
    long long v = std::strtoll(begin, &end, 10);
    while (end && std::isspace(static_cast<unsigned char>(*end))) ++end;
    if (end == begin || *end != '\0' || errno == ERANGE) throw ErrorAt(loc, "'{}' is not an integer", s);
    return v;
  }

  static std::vector<double> ParseList(const std::string& s, const Location& loc) {
    std::vector<double> out;
    std::string token;
    auto flush = [&] {
      if (!token.empty()) out.push_back(ParseDouble(token, loc));
      token.clear();
    };
    for (char c : s) {
      if (c == ',' || std::isspace(static_cast<unsigned char>(c))) flush();
      else token += c;
    }
    flush();
    return out;
  }

  Vec3d ParseTriple(const pugi::xml_node& n, const Location& loc, double fallback) const {
    if (n.attribute("value")) {
      if (n.attribute("x") || n.attribute("y") || n.attribute("z"))
        throw ErrorAt(loc, "<{}> takes either value or x, y, z, not both", n.name());
      std::vector<double> v = ParseList(Attr(n, "value", loc), loc);
      if (v.size() == 1) return Vec3d(v[0]);
      if (v.size() != 3) throw ErrorAt(loc, "<{}> value needs 1 or 3 numbers, got {}", n.name(), v.size());
      return {v[0], v[1], v[2]};
    }
    Vec3d r(fallback);
    const char* axes[3] = {"x", "y", "z"};
    for (int i = 0; i < 3; ++i)
      if (n.attribute(axes[i])) r[i] = ParseDouble(Attr(n, axes[i], loc), loc);
    return r;
  }

  Transform ParseTransform(const pugi::xml_node& n, const FileContext& ctx) const {
    Transform t;
    for (pugi::xml_node op : n.children()) {
      if (op.type() != pugi::node_element) continue;
      Location loc = Loc(ctx, op);
      std::string name = op.name();
      try {
        Transform m;
        if (name == "translate") {
          CheckAttributes(op, {"x", "y", "z", "value"}, loc);
          m = Transform::Translate(ParseTriple(op, loc, 0));
        } else if (name == "scale") {
          CheckAttributes(op, {"x", "y", "z", "value"}, loc);
          m = Transform::Scale(ParseTriple(op, loc, 1));
        } else if (name == "rotate") {
          CheckAttributes(op, {"x", "y", "z", "value", "angle"}, loc);
          m = Transform::Rotate(ParseDouble(Attr(op, "angle", loc), loc), ParseTriple(op, loc, 0));
        } else if (name == "matrix") {
          CheckAttributes(op, {"value"}, loc);
          std::vector<double> v = ParseList(Attr(op, "value", loc), loc);
          Matrix4 mat = Matrix4::Identity();
          if (v.size() == 16) {
            for (int i = 0; i < 16; ++i) mat.m[i / 4][i % 4] = v[i];
          } else if (v.size() == 9) {
            for (int i = 0; i < 9; ++i) mat.m[i / 3][i % 3] = v[i];
          } else {
            throw ErrorAt(loc, "<matrix> needs 16 (or 9) numbers, got {}", v.size());
          }
          m = Transform(mat);
        } else if (name == "lookat") {
          CheckAttributes(op, {"origin", "target", "up"}, loc);
          auto triple = [&](const char* attr) {
            std::vector<double> v = ParseList(Attr(op, attr, loc), loc);
            if (v.size() != 3) throw ErrorAt(loc, "lookat '{}' needs 3 numbers", attr);
            return Vec3d(v[0], v[1], v[2]);
          };
          Vec3d up = op.attribute("up") ? triple("up") : Vec3d(0, 1, 0);
          m = Transform::LookAt(triple("origin"), triple("target"), up);
        } else {
          throw ErrorAt(loc, "unknown transform operation <{}>", name);
        }
        t = m * t;  // later operations apply after earlier ones
        for (const auto& row : t.Matrix().m)
          for (double v : row)
            if (!std::isfinite(v)) throw ErrorAt(loc, "the transform overflows (its numbers are too large)");
      } catch (const std::invalid_argument& e) {
        throw ErrorAt(loc, "{}", e.what());
      }
    }
    return t;
  }

  SpectrumValue ParseSpectrum(const pugi::xml_node& n, const FileContext& ctx, const Location& loc) const {
    SpectrumValue s;
    std::string type = n.attribute("type") ? Attr(n, "type", loc) : "";
    // What each kind takes: attributes, and nested <float>s by name.
    const bool blackbody = type == "blackbody", illuminant = type == "d65" || type == "cie_a";
    if (!type.empty() && !blackbody && !illuminant)
      throw ErrorAt(loc, "unknown spectrum type '{}' (blackbody, d65, cie_a)", type);
    if (blackbody) CheckAttributes(n, {"name", "type", "temperature"}, loc);
    else if (illuminant) CheckAttributes(n, {"name", "type"}, loc);
    else CheckAttributes(n, {"name", "value", "filename"}, loc);
    for (pugi::xml_node c : n.children()) {
      if (c.type() != pugi::node_element) continue;
      std::string child = c.attribute("name").value();
      if (std::string(c.name()) != "float" || type.empty() || (child != "scale" && !(blackbody && child == "temperature")))
        throw ErrorAt(Loc(ctx, c), "a {} spectrum does not take <{} name=\"{}\">", type.empty() ? "sampled" : type, c.name(),
                      child);
    }
    auto nested_float = [&](const char* name, double fallback) {
      for (pugi::xml_node c : n.children("float"))
        if (Attr(c, "name", Loc(ctx, c)) == name) return ParseDouble(Attr(c, "value", Loc(ctx, c)), Loc(ctx, c));
      return fallback;
    };
    if (blackbody) {
      s.kind = SpectrumValue::Kind::kBlackbody;
      s.temperature = float(n.attribute("temperature") ? ParseDouble(Attr(n, "temperature", loc), loc)
                                                       : nested_float("temperature", -1));
      // Beyond this range Planck's law over- or underflows to a NaN spectrum.
      if (!(s.temperature >= 1 && s.temperature <= 1e9))
        throw ErrorAt(loc, "blackbody spectrum needs a temperature from 1 to 1e9 K");
      s.value = float(nested_float("scale", 1));
      return s;
    }
    if (illuminant) {
      s.kind = type == "d65" ? SpectrumValue::Kind::kD65 : SpectrumValue::Kind::kIlluminantA;
      s.value = float(nested_float("scale", 1));
      return s;
    }
    // (wavelength, value) pairs: "l:v, l:v, ..." in the value, or "l v" lines in a file (Mitsuba's .spd).
    struct Entry {
      std::string lambda, value;
      Location at;
    };
    std::vector<Entry> entries;
    if (n.attribute("filename")) {
      if (n.attribute("value")) throw ErrorAt(loc, "<spectrum> takes either value or filename, not both");
      fs::path file = fs::path(ctx.path).parent_path() / Attr(n, "filename", loc);
      if (!fs::exists(file)) throw ErrorAt(loc, "cannot open spectrum file '{}'", file.string());
      std::istringstream lines(ReadTextFile(file.string(), "spectrum file"));
      std::string line;
      int number = 0;
      while (std::getline(lines, line)) {
        ++number;
        if (size_t h = line.find('#'); h != std::string::npos) line.resize(h);
        std::vector<std::string> f = SplitFields(line);
        if (f.empty()) continue;
        if (f.size() != 2) throw MakeInputError(file.string(), number, "a spectrum line is: wavelength value");
        entries.push_back({f[0], f[1], {file.string(), number}});
      }
    } else {
      std::string value = Attr(n, "value", loc);
      if (value.find(':') == std::string::npos) {
        s.kind = SpectrumValue::Kind::kConstant;
        s.value = float(ParseDouble(value, loc));
        return s;
      }
      // Entries separated by commas, spaces or both, as Mitsuba 3 tokenizes them.
      std::replace(value.begin(), value.end(), ',', ' ');
      for (const std::string& token : SplitFields(value)) {
        size_t colon = token.find(':');
        if (colon == std::string::npos) throw ErrorAt(loc, "spectrum entry '{}' is not lambda:value", token);
        entries.push_back({token.substr(0, colon), token.substr(colon + 1), loc});
      }
    }
    s.kind = SpectrumValue::Kind::kSampled;
    for (const Entry& e : entries) {
      float l = float(ParseDouble(e.lambda, e.at)), v = float(ParseDouble(e.value, e.at));
      if (!s.lambdas.empty() && l <= s.lambdas.back()) throw ErrorAt(e.at, "spectrum wavelengths must increase");
      s.lambdas.push_back(l);
      s.values.push_back(v);
    }
    if (s.lambdas.size() < 2) throw ErrorAt(loc, "a sampled spectrum needs at least two entries");
    return s;
  }

  static bool IsObjectTag(const std::string& t) {
    static const char* tags[] = {"bsdf",    "texture", "shape",   "emitter",    "sensor", "film",
                                 "sampler", "rfilter", "integrator", "medium", "phase"};
    return std::any_of(std::begin(tags), std::end(tags), [&](const char* x) { return t == x; });
  }

  // A named texture is the property of that name (a BSDF's "reflectance"); any other object's
  // name is only a key, as in Mitsuba 3, whose plugins find their BSDF, emitter, film or
  // sampler (and the scene its objects) by kind.
  void Attach(ObjectNode& parent, std::shared_ptr<ObjectNode> obj, const std::string& name, const Location& loc) {
    // Through <ref>s an object can sit deeper than its element: bound every walk over the tree.
    parent.height = std::max(parent.height, obj->height + 1);
    if (parent.height > kMaxObjectNesting)
      throw ErrorAt(loc, "objects nested more than {} levels deep (counting those <ref>s bring in)", kMaxObjectNesting);
    // A medium is bound by name as Mitsuba 3 binds it: a shape's interior or exterior, the
    // sensor's (named or not) medium; elsewhere it has no meaning. A phase function belongs in
    // a medium.
    if (obj->tag == "medium") {
      if (parent.tag == "shape") {
        if (name != "interior" && name != "exterior")
          throw ErrorAt(loc, "a <medium> in a <shape> needs name=\"interior\" or name=\"exterior\"{}",
                        name.empty() ? "" : fmt::format(", not '{}'", name));
        AddProperty(parent, Property{name, std::move(obj), "object", loc});
        return;
      }
      if (parent.tag == "sensor") {
        if (!name.empty() && name != "medium")
          throw ErrorAt(loc, "the <medium> of a <sensor> is unnamed (or named 'medium'), not '{}'", name);
        AddProperty(parent, Property{"medium", std::move(obj), "object", loc});
        return;
      }
      if (parent.tag != "scene")
        throw ErrorAt(loc, "a <medium> belongs in a <shape> (its interior or exterior), in the <sensor> or in the "
                      "<scene> (with an id, for <ref>s), not in a <{}>", parent.tag);
    }
    if (obj->tag == "phase" && parent.tag != "medium")
      throw ErrorAt(loc, "a <phase> belongs in a <medium>, not in a <{}>", parent.tag);
    if (name.empty() || obj->tag != "texture") {
      parent.children.push_back(std::move(obj));
    } else {
      AddProperty(parent, Property{name, std::move(obj), "object", loc});
    }
  }

  void AddProperty(ObjectNode& parent, Property p) {
    for (const Property& q : parent.props)
      if (q.name == p.name)
        throw ErrorAt(p.loc, "property '{}' given twice (first at line {})", p.name, q.loc.line);
    parent.props.push_back(std::move(p));
  }

  // `depth`: how many objects enclose the children of `node` (0 at the scene's root).
  void Walk(const pugi::xml_node& node, const FileContext& ctx, ObjectNode& parent, int include_depth, int depth) {
    for (pugi::xml_node c : node.children()) {
      if (c.type() != pugi::node_element) continue;
      std::string tag = c.name();
      Location loc = Loc(ctx, c);
      if (tag == "default") {
        CheckAttributes(c, {"name", "value"}, loc);
        std::string name = c.attribute("name").value();
        if (name.empty()) throw ErrorAt(loc, "<default> needs a name");
        declared_.insert(name);
        if (!overridden_.count(name)) params_[name] = Attr(c, "value", loc);
      } else if (tag == "include") {
        CheckAttributes(c, {"filename"}, loc);
        if (include_depth >= kMaxIncludeDepth)
          throw ErrorAt(loc, "includes nested more than {} deep (a cycle?)", kMaxIncludeDepth);
        if (++includes_ > kMaxIncludes) throw ErrorAt(loc, "more than {} <include>s in all", kMaxIncludes);
        fs::path inc = fs::path(ctx.path).parent_path() / Attr(c, "filename", loc);
        std::string text;
        try {
          text = ReadTextFile(inc.string(), "included file");
        } catch (const InputError& e) {
          throw ErrorAt(loc, "{}", e.what());
        }
        pugi::xml_document doc;
        FileContext sub = Load(text, inc.string(), &doc);
        pugi::xml_node scene = doc.child("scene");
        if (!scene) throw MakeInputError(inc.string(), 1, "an included file must have a <scene> root");
        CheckAttributes(scene, {"version"}, Loc(sub, scene));
        Walk(scene, sub, parent, include_depth + 1, depth);
      } else if (tag == "ref") {
        CheckAttributes(c, {"id", "name"}, loc);
        std::string id = Attr(c, "id", loc);
        auto it = ids_.find(id);
        if (it == ids_.end()) throw ErrorAt(loc, "reference to unknown id '{}'", id);
        Attach(parent, it->second, Attr(c, "name", loc, false), loc);
      } else if (tag == "alias") {  // Mitsuba 3: the object `id` also known as `as`
        CheckAttributes(c, {"id", "as"}, loc);
        std::string id = Attr(c, "id", loc), as = Attr(c, "as", loc);
        auto it = ids_.find(id);
        if (it == ids_.end()) throw ErrorAt(loc, "alias of unknown id '{}'", id);
        if (ids_.count(as)) throw ErrorAt(loc, "id '{}' is used twice", as);
        ids_[as] = it->second;
      } else if (IsObjectTag(tag)) {
        CheckAttributes(c, {"type", "id", "name"}, loc);
        if (depth >= kMaxObjectNesting) throw ErrorAt(loc, "objects nested more than {} levels deep", kMaxObjectNesting);
        auto obj = std::make_shared<ObjectNode>();
        obj->tag = tag;
        obj->type = Attr(c, "type", loc);
        obj->id = Attr(c, "id", loc, false);
        obj->loc = loc;
        Walk(c, ctx, *obj, include_depth, depth + 1);
        if (!obj->id.empty()) {
          if (ids_.count(obj->id)) throw ErrorAt(loc, "id '{}' is used twice", obj->id);
          ids_[obj->id] = obj;
        }
        Attach(parent, obj, Attr(c, "name", loc, false), loc);
      } else if (tag == "float" || tag == "integer" || tag == "boolean" || tag == "string" || tag == "rgb" ||
                 tag == "spectrum" || tag == "point" || tag == "vector" || tag == "transform") {
        Property p;
        p.name = Attr(c, "name", loc);
        p.type_name = tag;
        p.loc = loc;
        if (tag == "float") {
          CheckAttributes(c, {"name", "value"}, loc);
          p.data = ParseDouble(Attr(c, "value", loc), loc);
        } else if (tag == "integer") {
          CheckAttributes(c, {"name", "value"}, loc);
          p.data = ParseInt(Attr(c, "value", loc), loc);
        } else if (tag == "boolean") {
          CheckAttributes(c, {"name", "value"}, loc);
          std::string v = Attr(c, "value", loc);
          for (char& ch : v) ch = char(std::tolower(static_cast<unsigned char>(ch)));  // "True" as Mitsuba
          if (v != "true" && v != "false") throw ErrorAt(loc, "'{}' is not a boolean (true or false)", v);
          p.data = (v == "true");
        } else if (tag == "string") {
          CheckAttributes(c, {"name", "value"}, loc);
          p.data = Attr(c, "value", loc);
        } else if (tag == "rgb") {
          CheckAttributes(c, {"name", "value"}, loc);
          std::vector<double> v = ParseList(Attr(c, "value", loc), loc);
          if (v.size() == 1) v = {v[0], v[0], v[0]};
          if (v.size() != 3) throw ErrorAt(loc, "<rgb> needs 1 or 3 numbers, got {}", v.size());
          SpectrumValue s;
          s.kind = SpectrumValue::Kind::kRgb;
          s.rgb = Vec3f(float(v[0]), float(v[1]), float(v[2]));
          p.data = s;
        } else if (tag == "spectrum") {
          p.data = ParseSpectrum(c, ctx, loc);  // checks its attributes by kind
        } else if (tag == "point" || tag == "vector") {
          CheckAttributes(c, {"name", "value", "x", "y", "z"}, loc);
          p.data = ParseTriple(c, loc, 0);
        } else {
          CheckAttributes(c, {"name"}, loc);
          p.data = ParseTransform(c, ctx);
        }
        AddProperty(parent, std::move(p));
      } else {
        throw ErrorAt(loc, "unknown element <{}>", tag);
      }
    }
  }

  std::map<std::string, std::string> params_;
  std::map<std::string, bool> overridden_;
  mutable std::set<std::string> declared_;  // names given a <default> or used as $name
  std::map<std::string, std::shared_ptr<ObjectNode>> ids_;
  size_t xml_bytes_ = 0;
  mutable size_t substituted_bytes_ = 0;  // counted by the const readers of attributes
  int includes_ = 0;
};

}  // namespace

SceneDocument ParseSceneFile(const std::string& path, const std::map<std::string, std::string>& defines) {
  return Parser(defines).ParseFile(path);
}

SceneDocument ParseSceneString(const std::string& xml, const std::string& name,
                               const std::map<std::string, std::string>& defines) {
  return Parser(defines).ParseString(xml, name);
}

}  // namespace objektiv
