// libFuzzer target: animation files (rig, clips, easings), then the rig and clips compiled from them, as the
// game does with assets/animations/robot.json.
#include "anim/clip_io.h"
#include "fuzz_oracle.h"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const std::string file_name = "fuzz.json";
    auto file = ks::anim::load_animation_string(text, file_name);
    if (!file.ok()) {
        ks::fuzz::check_clear_error(file.error(), file_name);
        return 0;
    }
    const std::string saved = ks::anim::save_animation_string(*file);
    auto again = ks::anim::load_animation_string(saved, "fuzz-resaved.json");
    if (!again.ok()) ks::fuzz::fail("a loaded file does not reload after saving", again.error().str());
    if (ks::anim::save_animation_string(*again) != saved)
        ks::fuzz::fail("save -> load -> save changed the text", saved);
    // A valid file must also bind to the rig it describes (rig or clip errors are values, never crashes).
    auto rig = ks::anim::build_rig(*file);
    if (rig.ok()) {
        auto clips = ks::anim::compile(*file, *rig);
        if (!clips.ok() && clips.error().message.empty()) ks::fuzz::fail("compile error without a message");
    } else if (rig.error().message.empty()) {
        ks::fuzz::fail("rig error without a message");
    }
    return 0;
}
