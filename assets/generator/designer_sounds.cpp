#include "designer_sounds.h"

#include "core/files.h"
#include "jsonio/suggest.h"

#include <algorithm>
#include <sstream>

namespace ks::assetgen {

Result<std::set<std::string>> load_designer_sounds(const std::filesystem::path& file,
                                                   const std::vector<std::string>& known) {
    std::set<std::string> names;
    if (!std::filesystem::exists(file)) return names;
    auto text = files::read_text(file);
    if (!text) return text.error();
    std::istringstream lines(*text);
    std::string line;
    for (int number = 1; std::getline(lines, line); ++number) {
        line = line.substr(0, line.find('#'));
        const auto first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos) continue;
        const std::string name = line.substr(first, line.find_last_not_of(" \t\r") - first + 1);
        if (std::find(known.begin(), known.end(), name) == known.end()) {
            const std::string guess = jsonio::closest_match(name, known);
            return Error("no sound named '" + name + "'", Location{file.string(), number},
                         guess.empty() ? "the names are the sounds of ks_assetgen --list"
                                       : "did you mean '" + guess + "'?");
        }
        names.insert(name);
    }
    return names;
}

} // namespace ks::assetgen
