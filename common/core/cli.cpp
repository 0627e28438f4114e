#include "core/cli.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>

namespace ks {

Result<CommandLine> CommandLine::parse(int argc, const char* const* argv, const std::vector<std::string>& flags) {
    CommandLine cl;
    for (int i = 1; i < argc; ++i) {
        std::string arg = argv[i];
        if (arg.rfind("--", 0) != 0 || arg.size() == 2) {
            cl.positional_.push_back(arg);
            continue;
        }
        std::string name = arg.substr(2);
        if (auto eq = name.find('='); eq != std::string::npos) {
            cl.values_[name.substr(0, eq)] = name.substr(eq + 1);
            continue;
        }
        if (std::find(flags.begin(), flags.end(), name) != flags.end()) {
            cl.values_[name] = "";
            continue;
        }
        if (i + 1 >= argc) return Error("option --" + name + " needs a value", Location{"command line"});
        cl.values_[name] = argv[++i];
    }
    return cl;
}

std::optional<std::string> CommandLine::get(const std::string& name) const {
    auto it = values_.find(name);
    if (it == values_.end()) return std::nullopt;
    return it->second;
}

std::string CommandLine::get_or(const std::string& name, const std::string& fallback) const {
    return get(name).value_or(fallback);
}

Result<int> CommandLine::get_int(const std::string& name, int fallback, int min, int max) const {
    auto text = get(name);
    if (!text) return fallback;
    int value = 0;
    auto [end, ec] = std::from_chars(text->data(), text->data() + text->size(), value);
    if (ec != std::errc() || end != text->data() + text->size() || value < min || value > max)
        return Error("--" + name + " must be a whole number from " + std::to_string(min) + " to " +
                         std::to_string(max) + ", got '" + *text + "'",
                     Location{"command line"});
    return value;
}

Result<double> CommandLine::get_double(const std::string& name, double fallback) const {
    auto text = get(name);
    if (!text) return fallback;
    char* end = nullptr;
    double value = std::strtod(text->c_str(), &end);
    if (text->empty() || *end != '\0' || !std::isfinite(value))
        return Error("--" + name + " must be a finite number, got '" + *text + "'", Location{"command line"});
    return value;
}

std::vector<std::string> CommandLine::unknown(const std::vector<std::string>& known) const {
    std::vector<std::string> out;
    for (auto& [name, value] : values_)
        if (std::find(known.begin(), known.end(), name) == known.end()) out.push_back("--" + name);
    return out;
}

} // namespace ks
