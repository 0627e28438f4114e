// libFuzzer target: campaign files (levels in order with titles). Level files are looked up in the shipped
// levels/ folder, so "main.json" exists and other names are missing-file errors.
#include "fuzz_oracle.h"
#include "level/campaign.h"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const std::string file_name = "fuzz-campaign.json";
    const std::filesystem::path folder = std::filesystem::path(KS_SOURCE_DIR) / "levels";
    auto campaign = ks::level::load_campaign_string(text, file_name, folder);
    if (!campaign.ok()) {
        ks::fuzz::check_clear_error(campaign.error(), file_name);
        return 0;
    }
    if (campaign->levels.empty()) ks::fuzz::fail("accepted a campaign without levels", text);
    const std::string saved = ks::level::save_campaign_string(*campaign);
    auto again = ks::level::load_campaign_string(saved, "fuzz-resaved.json", folder);
    if (!again.ok()) ks::fuzz::fail("a loaded campaign does not reload after saving", again.error().str());
    if (ks::level::save_campaign_string(*again) != saved)
        ks::fuzz::fail("save -> load -> save changed the text", saved);
    return 0;
}
