// The parameters and techniques the preset, script, bookmark and command-line targets check their
// input against: a built-in scene's parameters (camera.*, light0.*, ...) and two GL-free
// techniques with a parameter of every kind (tests/support/fake_technique.h), built once.
#pragma once
#include "frame/param_catalog.h"
#include "frame/registry.h"
#include "params/param_set.h"
#include "scene/builtin.h"

#include "fake_technique.h"

namespace rtlab::fuzz {

inline const TechniqueRegistry& registry() {
  static const TechniqueRegistry r = [] {
    TechniqueRegistry reg;
    reg.add(test::fakeTechnique("sh", "shadow",
                                {ParamSpec::integer("sh.samples", "Samples", 16, 1, 64),
                                 ParamSpec::real("sh.bias", "Bias", 0.005, 0.0, 0.1),
                                 ParamSpec::boolean("sh.pcf", "PCF", true),
                                 ParamSpec::choice("sh.filter", "Filter", {"box", "poisson"}, 0)},
                                {{"sh.depth", 1, ""}}));
    reg.add(test::fakeTechnique("occ", "ao",
                                {ParamSpec::real("occ.radius", "Radius", 0.5, 0.0, 2.0),
                                 ParamSpec::vector3("occ.axis", "Axis", {0, 1, 0}, -1, 1),
                                 ParamSpec::color("occ.tint", "Tint", {1, 1, 1})}));
    return reg;
  }();
  return r;
}

// The parameters of the built-in "contact" scene with registry()'s techniques; copy before use.
inline const ParamSet& params() {
  static const ParamSet p = makeParamSet(makeBuiltinScene("contact"), registry());
  return p;
}

} // namespace rtlab::fuzz
