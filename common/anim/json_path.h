#pragma once
// JSON paths for error messages ("clips[2].phases[0].targets.chest.rot[1]") and finding where such a path's
// value starts in the source text, so a problem found after parsing still gets a line:column.
// (nlohmann_json 3.11 keeps no source positions.)
#include <string>
#include <string_view>
#include <vector>

namespace ks::anim {

struct JsonPathStep {
    std::string key; // object member, when index < 0
    long index = -1; // array element
};

class JsonPath {
  public:
    JsonPath() = default;
    JsonPath operator/(std::string_view key) const;
    JsonPath operator[](std::size_t index) const;
    const std::vector<JsonPathStep>& steps() const { return steps_; }
    std::string str() const; // "" for the document root

  private:
    std::vector<JsonPathStep> steps_;
};

struct TextPosition {
    int line = 0, column = 0; // 1-based; 0 = unknown
};

TextPosition line_column(std::string_view text, std::size_t byte_offset);
// Where the value at `path` starts in valid JSON `text`; {0, 0} if the path is not there.
TextPosition locate(std::string_view text, const JsonPath& path);

} // namespace ks::anim
