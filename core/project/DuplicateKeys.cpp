#include "project/DuplicateKeys.h"

#include <set>

namespace rollsim {

namespace {
/// SAX events of nlohmann's parser, keeping the path to the current value and each open object's keys.
class KeyCollector : public nlohmann::json_sax<json> {
 public:
  std::vector<Issue> issues;

  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(number_integer_t) override { return value(); }
  bool number_unsigned(number_unsigned_t) override { return value(); }
  bool number_float(number_float_t, const string_t&) override { return value(); }
  bool string(string_t&) override { return value(); }
  bool binary(binary_t&) override { return value(); }
  bool start_object(std::size_t) override { return open(false); }
  bool start_array(std::size_t) override { return open(true); }
  bool end_object() override { return close(); }
  bool end_array() override { return close(); }
  bool key(string_t& k) override {
    Level& l = levels_.back();
    l.key = k;
    if (!l.keys.insert(k).second)
      issues.push_back({path(), "is given twice in one object (JSON keeps only the last): remove one"});
    return true;
  }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override { return false; }

 private:
  struct Level {
    bool array = false;
    long index = -1;  // an array's current element
    std::string key;  // an object's current key
    std::set<std::string> keys;
  };
  bool value() {  // a value completes an element of the enclosing array
    if (!levels_.empty() && levels_.back().array) ++levels_.back().index;
    return true;
  }
  bool open(bool array) {
    value();
    levels_.push_back({array, -1, "", {}});
    return true;
  }
  bool close() {
    levels_.pop_back();
    return true;
  }
  std::string path() const {
    std::string p;
    for (const Level& l : levels_)
      if (l.array)
        p += "[" + std::to_string(l.index) + "]";
      else if (!l.key.empty())
        p += (p.empty() ? "" : ".") + l.key;
    return p;
  }
  std::vector<Level> levels_;
};
}  // namespace

std::vector<Issue> duplicate_keys(const std::string& text) {
  KeyCollector keys;
  json::sax_parse(text, &keys);
  return keys.issues;
}

}  // namespace rollsim
