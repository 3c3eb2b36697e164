#include "partition/PartitionSpec.h"

#include <algorithm>
#include <cctype>
#include <charconv>

#include "partition/MetisPartition.h"
#include "partition/StructuredPartition.h"

namespace rollsim {

namespace {
const char* kExpected = "expected slice counts such as \"4x4\" or \"2x2x1\", or \"metis:N\"";

[[noreturn]] void fail(const std::string& text, const std::string& why) {
  throw PartitionError({{"partition", "\"" + text + "\": " + why}});
}

/// Strict positive integer: digits only, no sign, no spaces, fits an int.
bool parse_count(const std::string& s, int& value) {
  if (s.empty() || !std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isdigit(c); })) return false;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  return ec == std::errc() && end == s.data() + s.size();
}

PartitionSpec parse_metis(const std::string& text, const std::string& count) {
  PartitionSpec spec;
  spec.kind = PartitionKind::Metis;
  if (!parse_count(count, spec.parts))
    fail(text, "the number of subdomains after \"metis:\" must be a positive integer");
  if (spec.parts < 1) fail(text, "the number of subdomains must be at least 1");
  return spec;
}

std::vector<std::string> split_on_x(const std::string& s) {
  std::vector<std::string> parts(1);
  for (char c : s) {
    if (c == 'x' || c == 'X')
      parts.emplace_back();
    else
      parts.back() += c;
  }
  return parts;
}

PartitionSpec parse_slices(const std::string& text) {
  const std::vector<std::string> parts = split_on_x(text);
  if (parts.size() < 2 || parts.size() > 3) fail(text, kExpected);
  PartitionSpec spec;
  spec.axes = static_cast<int>(parts.size());
  for (size_t a = 0; a < parts.size(); ++a) {
    if (!parse_count(parts[a], spec.slices[a])) fail(text, kExpected);
    if (spec.slices[a] < 1) fail(text, std::string("the slice count along ") + "xyz"[a] + " must be at least 1");
  }
  return spec;
}
}  // namespace

PartitionSpec parse_partition_spec(const std::string& raw) {
  const auto first = raw.find_first_not_of(" \t"), last = raw.find_last_not_of(" \t");
  const std::string text = first == std::string::npos ? "" : raw.substr(first, last - first + 1);
  if (text.empty()) throw PartitionError({{"partition", std::string("empty partition: ") + kExpected}});
  const std::string prefix = "metis:";
  std::string lower = text;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
  if (lower.rfind(prefix, 0) == 0) return parse_metis(text, text.substr(prefix.size()));
  return parse_slices(text);
}

std::string to_string(const PartitionSpec& spec) {
  switch (spec.kind) {
    case PartitionKind::Metis:
      return "metis:" + std::to_string(spec.parts);
    case PartitionKind::Explicit:
      return "explicit";
    case PartitionKind::Structured:
      break;
  }
  std::string s = std::to_string(spec.slices[0]) + "x" + std::to_string(spec.slices[1]);
  return spec.axes == 3 ? s + "x" + std::to_string(spec.slices[2]) : s;
}

std::string oversized_partition(const Mesh& mesh, const PartitionSpec& spec) {
  const long long elements = mesh.num_elements();
  if (spec.kind == PartitionKind::Explicit) {
    for (size_t e = 0; e < spec.map.size(); ++e)
      if (spec.map[e] >= elements)
        return "element " + std::to_string(e) + " has subdomain id " + std::to_string(spec.map[e]) +
               ", but ids must be below the number of elements (" + std::to_string(elements) +
               "): every subdomain needs at least one element";
    return "";
  }
  long long asked = spec.kind == PartitionKind::Metis ? spec.parts : 1;
  if (spec.kind == PartitionKind::Structured)
    for (int a = 0; a < spec.axes; ++a) asked *= spec.slices[a];  // ≤ (2^31)^3: no overflow in 64 bits
  if (asked <= elements) return "";
  return "'" + to_string(spec) + "' asks for " + std::to_string(asked) + " subdomains, but the body has only " +
         std::to_string(elements) + " elements: every subdomain needs at least one";
}

Partition make_partition(const Mesh& mesh, const PartitionSpec& spec) {
  if (spec.kind == PartitionKind::Structured) return structured_partition(mesh, spec.slices);
  if (spec.kind == PartitionKind::Metis) return metis_partition(mesh, spec.parts);
  Partition p;
  p.element_subdomain = spec.map;
  p.description = "explicit";
  const int largest = spec.map.empty() ? 0 : *std::max_element(spec.map.begin(), spec.map.end());
  p.num_subdomains = spec.num_subdomains >= 0 ? spec.num_subdomains : std::max(1, largest + 1);
  return p;
}

}  // namespace rollsim
