#pragma once
// A tiny command-line parser shared by the executables: "--name value", "--name=value" and "--flag".
#include "core/math.h"
#include "core/result.h"

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ks {

class CommandLine {
  public:
    // `flags` are options that take no value; every other "--x" takes one.
    static Result<CommandLine> parse(int argc, const char* const* argv,
                                     const std::vector<std::string>& flags);

    bool has(const std::string& name) const { return values_.count(name) > 0; }
    std::optional<std::string> get(const std::string& name) const;
    std::string get_or(const std::string& name, const std::string& fallback) const;
    Result<int> get_int(const std::string& name, int fallback, int min, int max) const;
    Result<double> get_double(const std::string& name, double fallback) const;
    const std::vector<std::string>& positional() const { return positional_; }
    // Options given that are not in `known` (to report typos).
    std::vector<std::string> unknown(const std::vector<std::string>& known) const;

  private:
    std::map<std::string, std::string> values_;
    std::vector<std::string> positional_;
};

// A place and a facing given as one value, "x,y,z,yaw,pitch" (metres, then degrees; yaw 0 looks along -z):
// --camera of both executables, --warp of the game.
struct PoseArgument {
    Vec3 position{0.0f};
    float yaw_degrees = 0.0f;
    float pitch_degrees = 0.0f;
};
// Exactly five finite numbers separated by commas (spaces around them allowed), nothing else. The error
// names the value at fault; callers put the option's name and text in front of it.
Result<PoseArgument> parse_pose(std::string_view text);

} // namespace ks
