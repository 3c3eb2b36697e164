#pragma once
// The words of an enumerated option (a project file's, the command line's, the window's combo box's and
// summary.json's), written once per enum as a specialization of words<E>() in enum order, beside the enum.
// Header-only: the petsc module, which links nothing of rollsim_core, reads the same words.
#include <stdexcept>
#include <string>
#include <vector>

namespace rollsim {

template <class E>
const std::vector<std::string>& words();

/// The word of a choice.
template <class E>
const std::string& word(E e) {
  return words<E>().at(static_cast<size_t>(e));
}

/// The choice a word names; std::invalid_argument listing the valid words otherwise (a validated project never gets
/// there).
template <class E>
E from_word(const std::string& w) {
  const auto& all = words<E>();
  for (size_t i = 0; i < all.size(); ++i)
    if (all[i] == w) return static_cast<E>(i);
  std::string valid;
  for (const auto& a : all) valid += (valid.empty() ? "" : ", ") + a;
  throw std::invalid_argument("'" + w + "' is not one of " + valid);
}

}  // namespace rollsim
