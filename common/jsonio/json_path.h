#pragma once
// JSON paths as designers read them in messages: "clips[2].phases[0].targets.chest.rot[1]". Code that walks
// a parsed document builds them step by step (JsonPath) or as plain strings (member_path, element_path);
// both give the same text, which is what PositionMap looks up.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace ks::jsonio {

// "parent.key", or "key" at the root.
std::string member_path(const std::string& parent, std::string_view key);
// "parent[index]".
std::string element_path(const std::string& parent, std::size_t index);

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

} // namespace ks::jsonio
