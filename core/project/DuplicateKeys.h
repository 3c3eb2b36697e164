#pragma once
// A key given twice in one JSON object: nlohmann keeps the last silently, so a project that sets
// `"reduction": 0.2` and, further down, `"reduction": 0.3` would run with 0.3 and no word. Found on the text,
// before it is parsed into objects, with the path of the object (as the schema's issues name paths).
#include <string>
#include <vector>

#include "base/Schema.h"

namespace rollsim {

/// One issue per key repeated within an object of `text` (valid JSON), at the key's path.
std::vector<Issue> duplicate_keys(const std::string& text);

}  // namespace rollsim
