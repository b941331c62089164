#pragma once
// The contact laws a scenario may name (`[contact] model`), in the order
// messages list them. A law is a type with its name, the [[materials]] keys it
// needs (core/declared_keys.hpp), make() and compute() (see linear.hpp); adding
// one is its header plus its entry here.
#include "talus/core/declared_keys.hpp"
#include "talus/dem/contact/hertz_mindlin.hpp"
#include "talus/dem/contact/linear.hpp"

namespace talus::dem {

using ContactLaws = LawList<LinearSpringDashpot, HertzMindlin, ViscoelasticHertz>;

}  // namespace talus::dem
