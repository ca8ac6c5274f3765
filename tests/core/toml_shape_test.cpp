#include "core/toml_shape.hpp"

#include <gtest/gtest.h>

#include <string>

namespace cerebellum {
namespace {

std::string dotted_key(int parts, const std::string& part = "a") {
  std::string key = part;
  for (int i = 1; i < parts; ++i) key += "." + part;
  return key;
}

TEST(TomlShape, AGaitFileWithHeadersArraysFloatsAndCommentsIsWithinTheLimits) {
  const std::string text =
      "# Gait Params\n[[step]]\nmode = 11 # walk\nvel_des = [0.1, -2.5e-3, 1.0]\nname = "
      "\"a.b.c.d.e.f.g.h.i.j.k.l.m.n.o.p.q\"\n"
      "when = 1979-05-27T07:32:00.999\nnote = '''x.y.z.\n.a.b.c.d.e.f.g.h.i.j.k.l.m.n.o.p'''\n";
  EXPECT_EQ(toml_shape_problem(text), "");
}

TEST(TomlShape, CountsThePartsOfBareQuotedAndSpacedDottedKeys) {
  const TomlShapeLimits limits{4, 16};
  EXPECT_EQ(toml_shape_problem(dotted_key(4) + " = 1\n", limits), "");
  EXPECT_NE(toml_shape_problem(dotted_key(5) + " = 1\n", limits), "");
  EXPECT_NE(toml_shape_problem("\"a\".\"b\" . c . 'd'.e = 1\n", limits), "");
  EXPECT_NE(toml_shape_problem("[" + dotted_key(5, "1") + "]\n", limits), "");
  // a new line, '=' or ',' starts a new key: many short keys are fine
  EXPECT_EQ(toml_shape_problem("a.b = 1\nc.d = 2\ne = {f.g = 1, h.i = 2}\n", limits), "");
}

TEST(TomlShape, CountsOpenArraysAndInlineTablesAcrossLines) {
  const TomlShapeLimits limits{16, 3};
  EXPECT_EQ(toml_shape_problem("x = [[1], [2]]\n[[step]]\n", limits), "");
  EXPECT_NE(toml_shape_problem("x = [\n[\n{y = [1]}\n]\n]\n", limits), "");
  EXPECT_EQ(toml_shape_problem("x = \"[[[[[[\"\ny = '{{{{{{'\n", limits), "");
}

TEST(TomlShape, NamesTheLineOfTheProblem) {
  const std::string problem = toml_shape_problem("a = 1\n\n" + dotted_key(40) + " = 1\n");
  EXPECT_NE(problem.find("line 3"), std::string::npos) << problem;
  EXPECT_NE(problem.find("dotted key"), std::string::npos) << problem;
}

}  // namespace
}  // namespace cerebellum
