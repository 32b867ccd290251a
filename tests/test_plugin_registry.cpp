// The plugin registry and Properties' declared reads: a plugin reads only what it declares
// (anything else is a programming error), enumerated strings come back as their values, and
// the sampler's type reaches the sampler without a detour through text.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <set>
#include <stdexcept>

#include "io/plugin_registry.h"
#include "io/scene_loader.h"

namespace objektiv {
namespace {

enum class Fruit { kApple, kPear };
constexpr Named<Fruit> kFruits[] = {{"apple", Fruit::kApple}, {"pear", Fruit::kPear}};
const std::vector<PropertyDecl> kNone;

// <thing type="t"> with the given properties (at lines 2, 3, ...).
std::shared_ptr<ObjectNode> Node(std::vector<std::pair<std::string, PropertyData>> props) {
  auto node = std::make_shared<ObjectNode>();
  node->tag = "thing";
  node->type = "t";
  node->loc = {"x.xml", 1};
  int line = 2;
  for (auto& [name, data] : props) {
    std::string type_name = std::holds_alternative<std::string>(data) ? "string" : "float";
    node->props.push_back({name, data, type_name, {"x.xml", line++}});
  }
  return node;
}

template <typename F>
std::string InputErrorOf(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Properties, ReadsOnlyWhatIsDeclaredAsDeclared) {
  auto node = Node({{"size", 2.0}, {"name", std::string("pear")}});
  const std::vector<PropertyDecl> common = {{"size", PropType::kFloat}}, own = {{"name", PropType::kString}};
  Properties p(*node, common, own);
  EXPECT_EQ(p.Float("size"), 2.0);
  EXPECT_EQ(p.String("name"), "pear");
  EXPECT_THROW(p.Float("weight", 1), std::logic_error);  // not declared, even though absent
  EXPECT_THROW(p.Has("weight"), std::logic_error);
  EXPECT_THROW(p.Int("size", 0), std::logic_error);                          // declared as a float
  EXPECT_THROW(p.Children("size"), std::logic_error);                        // not a nested object
  EXPECT_THROW(p.Choice("name", Fruit::kApple, kFruits), std::logic_error);  // declared without choices
}

TEST(Properties, TellsAValuesType) {
  auto node = Node({{"ior", std::string("water")}, {"n", 1.5}});
  const std::vector<PropertyDecl> decls = {
      {"ior", PropType::kFloatOrString}, {"n", PropType::kFloatOrString}, {"k", PropType::kFloatOrString}};
  Properties p(*node, kNone, decls);
  EXPECT_EQ(p.TypeOf("ior"), ValueType::kString);
  EXPECT_EQ(p.TypeOf("n"), ValueType::kFloat);
  EXPECT_EQ(p.TypeOf("k"), std::nullopt);
}

TEST(Properties, TellsEveryValueTypeAsWritten) {
  SceneDocument doc = ParseSceneString(
      R"(<scene><bsdf type="t"><float name="f" value="1"/><integer name="i" value="1"/>
      <boolean name="b" value="true"/><string name="s" value="x"/><rgb name="c" value="1 0 0"/>
      <spectrum name="l" value="0.5"/><point name="p" value="1 2 3"/><vector name="v" value="0 0 1"/>
      <transform name="m"><translate x="1"/></transform><texture name="o" type="checkerboard"/></bsdf></scene>)",
      "x.xml", {});
  const std::vector<std::pair<std::string, ValueType>> expected = {
      {"f", ValueType::kFloat},    {"i", ValueType::kInteger}, {"b", ValueType::kBoolean},
      {"s", ValueType::kString},   {"c", ValueType::kRgb},     {"l", ValueType::kSpectrum},
      {"p", ValueType::kPoint},    {"v", ValueType::kVector},  {"m", ValueType::kTransform},
      {"o", ValueType::kObject}};
  std::vector<PropertyDecl> decls;
  for (const auto& [name, type] : expected) decls.push_back({name, PropType::kString});
  ASSERT_EQ(doc.root->children.size(), 1u);
  Properties p(*doc.root->children[0], kNone, decls);
  for (const auto& [name, type] : expected) EXPECT_EQ(p.TypeOf(name), type) << name;
}

TEST(Properties, ChoiceGivesTheValueOrListsTheChoices) {
  const std::vector<PropertyDecl> decls = {{"fruit", kFruits}};
  EXPECT_EQ(decls[0].choices, (std::vector<std::string>{"apple", "pear"}));
  auto pear = Node({{"fruit", std::string("pear")}});
  EXPECT_EQ(Properties(*pear, kNone, decls).Choice("fruit", Fruit::kApple, kFruits), Fruit::kPear);
  auto none = Node({});
  EXPECT_EQ(Properties(*none, kNone, decls).Choice("fruit", Fruit::kPear, kFruits), Fruit::kPear);
  // Without case.
  auto upper = Node({{"fruit", std::string("PeAr")}});
  EXPECT_EQ(Properties(*upper, kNone, decls).Choice("fruit", Fruit::kApple, kFruits), Fruit::kPear);
  auto plum = Node({{"fruit", std::string("plum")}});
  std::string msg = InputErrorOf([&] { Properties(*plum, kNone, decls).Choice("fruit", Fruit::kApple, kFruits); });
  EXPECT_NE(msg.find("x.xml:2:"), std::string::npos) << msg;
  EXPECT_NE(msg.find("'plum' is not one of: apple, pear"), std::string::npos) << msg;
  // A table other than the declared one is a programming error.
  constexpr Named<Fruit> kOther[] = {{"apple", Fruit::kApple}};
  EXPECT_THROW(Properties(*pear, kNone, decls).Choice("fruit", Fruit::kApple, kOther), std::logic_error);
}

using TestRegistry = PluginRegistry<int>;

TEST(PluginRegistry, FindsByTypeOrAliasAndListsAllWhenUnknown) {
  TestRegistry registry(
      "thing", {{"size", PropType::kFloat}},
      {{"t", {{"name", PropType::kString}}, [](const Properties& p) { return int(p.Float("size", 7)); }},
       {"u", {}, [](const Properties&) { return 1; }, {"a-u"}}});
  auto t = Node({{"size", 3.0}});
  EXPECT_EQ(registry.Build(*t), 3);
  auto alias = Node({});
  alias->type = "a-u";
  EXPECT_EQ(registry.Build(*alias), 1);
  alias->type = "v";
  std::string msg = InputErrorOf([&] { registry.Build(*alias); });
  EXPECT_NE(msg.find("x.xml:1: unknown thing type 'v' (known: a-u, t, u)"), std::string::npos) << msg;
  PluginKind kind = registry.Describe();
  EXPECT_EQ(kind.tag, "thing");
  ASSERT_EQ(kind.plugins.size(), 2u);
  EXPECT_EQ(kind.plugins[1].aliases, std::vector<std::string>{"a-u"});
}

TEST(PluginRegistry, RejectsATypeOrADeclarationGivenTwice) {
  auto one = [](const Properties&) { return 1; };
  EXPECT_THROW(TestRegistry("thing", {}, {{"t", {}, one}, {"u", {}, one, {"t"}}}), std::logic_error);
  EXPECT_THROW(TestRegistry("thing", {{"size", PropType::kFloat}}, {{"t", {{"size", PropType::kInteger}}, one}}),
               std::logic_error);
  // A property and a nested object may share a name.
  EXPECT_NO_THROW(TestRegistry("thing", {{"film", PropType::kString}}, {{"t", {{"film", PropType::kObject}}, one}}));
}

TEST(PluginRegistry, EveryKindOfSceneObjectHasOne) {
  std::set<std::string> tags;
  for (const PluginKind& kind : ScenePluginKinds()) tags.insert(kind.tag);
  EXPECT_EQ(tags, (std::set<std::string>{"bsdf", "emitter", "film", "integrator", "medium", "phase", "rfilter",
                                         "sampler", "sensor", "shape", "texture"}));
}

TEST(Samplers, TheTypeIsTheSamplersKind) {
  for (auto [type, kind] :
       {std::pair{"independent", SamplerKind::kIndependent}, std::pair{"stratified", SamplerKind::kStratified},
        std::pair{"multijitter", SamplerKind::kStratified}, std::pair{"orthogonal", SamplerKind::kStratified},
        std::pair{"sobol", SamplerKind::kSobol}, std::pair{"ldsampler", SamplerKind::kSobol}}) {
    RenderSetup s = LoadSceneFromString(
        fmt::format("<scene><sensor type=\"perspective\"><sampler type=\"{}\"/></sensor></scene>", type), "s.xml", {});
    EXPECT_EQ(s.sampler.kind, kind) << type;
    EXPECT_EQ(MakeSampler(s.sampler)->kind(), kind) << type;
  }
  RenderSetup s = LoadSceneFromString("<scene><sensor type=\"perspective\"/></scene>", "s.xml", {});
  EXPECT_EQ(s.sampler.kind, SamplerKind::kIndependent);
}

}  // namespace
}  // namespace objektiv
