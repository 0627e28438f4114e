// libFuzzer target: prefab files (each entity read by the level's reader), then a prefab placed in a frame
// and back, as the editor's palette does.
#include "fuzz_oracle.h"
#include "model/prefab.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const std::string file_name = "fuzz.prefab.json";
    std::vector<ks::Error> warnings;
    auto prefab = ks::editor::prefab_from_text(text, file_name, &warnings);
    if (!prefab.ok()) {
        ks::fuzz::check_clear_error(prefab.error(), file_name);
        return 0;
    }
    for (const ks::Error& w : warnings) ks::fuzz::check_clear_error(w, file_name);
    const std::string saved = ks::editor::prefab_to_text(*prefab);
    auto again = ks::editor::prefab_from_text(saved, "fuzz-resaved.prefab.json");
    if (!again.ok()) ks::fuzz::fail("a loaded prefab does not reload after saving", again.error().str());
    if (ks::editor::prefab_to_text(*again) != saved)
        ks::fuzz::fail("save -> load -> save changed the text", saved);
    // Placing a prefab and taking it back out of the same frame keeps every entity's place.
    const ks::editor::Frame frame{ks::Vec3(12.5f, 0.0f, -40.0f), 90.0f};
    for (const ks::level::Entity& entity : prefab->entities) {
        const ks::level::Entity back =
            ks::editor::entity_out_of_frame(ks::editor::entity_into_frame(entity, frame), frame);
        const ks::Vec3 d = back.position - entity.position;
        const float size = std::max(
            {1.0f, std::abs(entity.position.x), std::abs(entity.position.y), std::abs(entity.position.z)});
        // Single precision: a place far out loses its low bits in the turn, relative to its size.
        if (std::abs(d.x) + std::abs(d.y) + std::abs(d.z) > 1e-4f * size)
            ks::fuzz::fail("into and out of a frame moved an entity", saved);
    }
    return 0;
}
