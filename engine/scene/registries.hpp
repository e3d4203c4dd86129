// The part registries a scene draws from, with the built-in parts registered.
#pragma once

#include "controllers/controller_registry.hpp"
#include "detachment/criterion_registry.hpp"
#include "friction/friction_law_registry.hpp"
#include "profiles/profile_registry.hpp"

namespace mdrsim {

struct Registries {
  ProfileRegistry profiles;
  CriterionRegistry criteria;
  ControllerRegistry controllers;
  FrictionLawRegistry friction_laws;

  /// All built-in parts; a user adds their own with one add() call on the right registry.
  static Registries builtin() {
    Registries r;
    register_builtin_profiles(r.profiles);
    register_builtin_criteria(r.criteria);
    register_builtin_controllers(r.controllers);
    register_builtin_friction_laws(r.friction_laws);
    return r;
  }
};

}  // namespace mdrsim
