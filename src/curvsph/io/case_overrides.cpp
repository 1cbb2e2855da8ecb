#include "curvsph/io/case_overrides.hpp"

#include <charconv>

#include "curvsph/core/error.hpp"
#include "curvsph/io/quote.hpp"

namespace curvsph {
namespace {

std::vector<std::string> split_path(const std::string& path) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const auto dot = path.find('.', start);
    parts.push_back(path.substr(start, dot == std::string::npos ? std::string::npos : dot - start));
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  return parts;
}

bool parse_index(const std::string& s, std::size_t& out) {
  if (s.empty()) return false;
  auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return ec == std::errc() && ptr == s.data() + s.size();
}

}  // namespace

void apply_override(YAML::Node& root, const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError("--set", clip(assignment), "expected key.path=value");
  const std::string path = assignment.substr(0, eq);
  const std::string text = assignment.substr(eq + 1);
  YAML::Node value;
  try {
    value = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw InputError("--set", clip(path),
                     "value " + quote(text) + " is not valid YAML: " + clip(e.msg));
  }
  const auto parts = split_path(path);
  // yaml-cpp nodes are handles: walking with reset() keeps references into the tree.
  YAML::Node node;
  node.reset(root);
  std::string walked;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const std::string& part = parts[k];
    if (part.empty()) throw InputError("--set", path, "empty path component");
    walked += (walked.empty() ? "" : ".") + part;
    const bool last = k + 1 == parts.size();
    std::size_t index = 0;
    YAML::Node child;
    if (node.IsSequence()) {
      if (!parse_index(part, index))
        throw InputError("--set", walked, "is a list; address its elements by index");
      if (index > node.size())
        throw InputError(
            "--set", walked,
            "index out of range (the list has " + std::to_string(node.size()) + " elements)");
      if (index == node.size()) node.push_back(YAML::Node(YAML::NodeType::Map));
      child.reset(node[index]);
    } else {
      if (!node.IsMap() && !node.IsNull())
        throw InputError("--set", walked, "parent is a scalar, cannot hold a key");
      if (!node[part]) node[part] = YAML::Node(YAML::NodeType::Map);
      child.reset(node[part]);
    }
    if (last) {
      if (node.IsSequence())
        node[index] = value;
      else
        node[part] = value;
    } else {
      node.reset(child);
    }
  }
}

void apply_overrides(YAML::Node& root, const std::vector<std::string>& assignments) {
  for (const auto& a : assignments) apply_override(root, a);
}

}  // namespace curvsph
