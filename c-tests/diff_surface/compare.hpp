// Element-by-element comparison of two libraries' answers (see answers.hpp for the ids).
#pragma once

#include "answers.hpp"
#include "tm_answers.hpp"

namespace diffmesh {

// Compares `a` with `b` on every element both answered; every difference goes to `chk`
// with the element and both answers.
void compare(const Answers &a, const Answers &b, Checker &chk);

} // namespace diffmesh
