#pragma once
// The declared schema of a rollsim project file (see docs/project-format.md, generated from it).
#include "base/Schema.h"

namespace rollsim {

const ObjectSchema& project_schema();

/// docs/project-format.md: the field reference generated from project_schema().
std::string project_format_markdown();

/// Upper bound on elements of one model; larger requests are refused before any allocation.
constexpr double kMaxElements = 2.0e7;

}  // namespace rollsim
