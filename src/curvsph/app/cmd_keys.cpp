// `curvsph keys [PREFIX] [--markdown]`: the reference of every input key — type, range,
// default, unit and meaning — printed from the one schema (io/schema_table.cpp); docs/keys.md
// is `curvsph keys --markdown` (`make keys`).
#include <iostream>

#include "curvsph/app/command.hpp"
#include "curvsph/core/error.hpp"
#include "curvsph/io/case_schema.hpp"

namespace curvsph::app {
namespace {

std::string top_level_keys() {
  std::string list;
  for (const std::string& k : schema::children("")) list += (list.empty() ? "" : ", ") + k;
  return list;
}

const CommandRegistration reg{Command{
    "keys", "Every case-file key with its type, range, default, unit and meaning (docs/keys.md)",
    [](CLI::App& sub) -> std::function<int()> {
      auto prefix = std::make_shared<std::string>();
      auto markdown = std::make_shared<bool>(false);
      sub.add_option("PREFIX", *prefix,
                     "only the keys at or under this dotted path (boundary, walls, "
                     "walls.0.motion)");
      sub.add_flag("--markdown", *markdown, "the whole reference as Markdown (docs/keys.md)");
      return [prefix, markdown] {
        if (*markdown) {
          std::cout << schema::render_markdown();
          return 0;
        }
        const std::string text = schema::render_text(schema::pattern(*prefix));
        if (text.empty())
          throw InputError("", *prefix, "no such key (top-level keys: " + top_level_keys() + ")");
        std::cout << text;
        return 0;
      };
    },
    40}};

}  // namespace
}  // namespace curvsph::app
