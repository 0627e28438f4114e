#include "game/replay.h"

#include "core/files.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace ks::game {
namespace {

constexpr std::string_view kMagic = "killswitch-replay 1";

void append_float(std::string& out, float v) {
    char buffer[48];
    std::snprintf(buffer, sizeof buffer, "%a", static_cast<double>(v));
    out += buffer;
}

} // namespace

std::string save_recording_string(const Recording& r) {
    std::string out;
    out.reserve(64 + r.inputs.size() * 48);
    out += kMagic;
    out += "\nseed " + std::to_string(r.seed) + "\nlevel " + r.level + "\n";
    if (r.difficulty != Difficulty::Normal)
        out += std::string("difficulty ") + difficulty_name(r.difficulty) + "\n";
    out += "steps " + std::to_string(r.inputs.size()) + "\n";
    for (const Input& in : r.inputs) {
        append_float(out, in.move_forward);
        out += ' ';
        append_float(out, in.move_right);
        out += ' ';
        append_float(out, in.look_yaw);
        out += ' ';
        append_float(out, in.look_pitch);
        out += ' ';
        std::string flags;
        if (in.jump) flags += 'j';
        if (in.fire) flags += 'f';
        if (in.interact) flags += 'e';
        if (in.pause) flags += 'p';
        out += flags.empty() ? "-" : flags;
        out += '\n';
    }
    return out;
}

Result<void> save_recording_file(const std::filesystem::path& path, const Recording& recording) {
    return files::write_atomic(path, save_recording_string(recording));
}

Result<Recording> load_recording_string(std::string_view text, const std::string& file_name) {
    std::istringstream in{std::string(text)};
    std::string line;
    int line_no = 0;
    auto fail = [&](const std::string& message, const std::string& hint) {
        return Error(message, Location(file_name, line_no, 1), hint);
    };
    Recording r;
    auto next = [&]() {
        ++line_no;
        return static_cast<bool>(std::getline(in, line));
    };
    if (!next() || line != kMagic)
        return fail("not a Killswitch replay",
                    "the first line must be \"killswitch-replay 1\" (record one with --record)");
    if (!next() || line.rfind("seed ", 0) != 0)
        return fail("missing \"seed N\" line", "line 2 holds the seed the recording was made with");
    char* end = nullptr;
    r.seed = std::strtoull(line.c_str() + 5, &end, 10);
    if (end == line.c_str() + 5 || *end != '\0') return fail("seed is not a number", "write \"seed 42\"");
    if (!next() || line.rfind("level", 0) != 0)
        return fail("missing \"level PATH\" line", "line 3 names the level");
    r.level = line.size() > 6 ? line.substr(6) : "";
    if (!next()) return fail("missing \"steps N\" line", "line 4 holds the step count");
    if (line.rfind("difficulty ", 0) == 0) {
        auto difficulty = parse_difficulty(line.substr(11), Location(file_name, line_no, 12));
        if (!difficulty) return difficulty.error();
        r.difficulty = *difficulty;
        if (!next()) return fail("missing \"steps N\" line", "the step count follows the difficulty");
    }
    if (line.rfind("steps ", 0) != 0) return fail("missing \"steps N\" line", "line 4 holds the step count");
    const long long steps = std::strtoll(line.c_str() + 6, &end, 10);
    if (end == line.c_str() + 6 || *end != '\0' || steps < 0 || steps > 100'000'000)
        return fail("step count is not a number in 0..100000000", "write \"steps 3600\"");
    r.inputs.reserve(static_cast<std::size_t>(steps));
    while (next()) {
        if (line.empty()) continue;
        Input input;
        const char* p = line.c_str();
        float* fields[4] = {&input.move_forward, &input.move_right, &input.look_yaw, &input.look_pitch};
        for (float* f : fields) {
            const double v = std::strtod(p, &end);
            if (end == p || !std::isfinite(v) || std::abs(v) > 1e6)
                return fail("expected four finite numbers then flags",
                            "a step line looks like \"0x1p+0 0x0p+0 0x0p+0 0x0p+0 f\"");
            *f = static_cast<float>(v);
            p = end;
        }
        while (*p == ' ') ++p;
        for (; *p && *p != ' '; ++p) {
            switch (*p) {
            case 'j':
                input.jump = true;
                break;
            case 'f':
                input.fire = true;
                break;
            case 'e':
                input.interact = true;
                break;
            case 'p':
                input.pause = true;
                break;
            case '-':
                break;
            default:
                return fail(std::string("unknown flag '") + *p + "'",
                            "flags are j (jump), f (fire), e (interact), p (pause) or -");
            }
        }
        r.inputs.push_back(input);
    }
    if (static_cast<long long>(r.inputs.size()) != steps)
        return Error("replay has " + std::to_string(r.inputs.size()) + " step lines but its header says " +
                         std::to_string(steps),
                     Location(file_name, 4, 1), "the file is truncated or was edited; record it again");
    return r;
}

Result<Recording> load_recording_file(const std::filesystem::path& path) {
    auto text = files::read_text(path);
    if (!text) return text.error();
    return load_recording_string(*text, path.string());
}

} // namespace ks::game
