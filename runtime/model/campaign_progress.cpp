#include "runtime/model/campaign_progress.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ks::runtime {

std::string accuracy_text(int hits, int shots) {
    if (shots <= 0) return "-";
    const double percent = 100.0 * static_cast<double>(std::max(0, hits)) / static_cast<double>(shots);
    char text[32];
    std::snprintf(text, sizeof(text), "%d %%", static_cast<int>(std::lround(std::min(percent, 100.0))));
    return text;
}

std::string format_time(double seconds) {
    if (!std::isfinite(seconds) || seconds < 0.0 || seconds > 1.0e9) seconds = 0.0;
    // In tenths first, so 59.96 s reads "1:00.0", not "0:60.0".
    const long long tenths = std::llround(seconds * 10.0);
    char text[32];
    std::snprintf(text, sizeof(text), "%lld:%02lld.%lld", tenths / 600, tenths % 600 / 10, tenths % 10);
    return text;
}

void CampaignProgress::record_win(LevelResult result) {
    if (finished()) return;
    result.title = current().title;
    if (results_.size() > index_) results_.resize(index_);
    results_.push_back(std::move(result));
}

bool CampaignProgress::advance() {
    if (results_.size() <= index_ || on_last_level()) return false;
    ++index_;
    return true;
}

void CampaignProgress::restore(std::span<const LevelResult> won) {
    results_.assign(won.begin(), won.begin() + static_cast<std::ptrdiff_t>(std::min(won.size(), count())));
    for (std::size_t i = 0; i < results_.size(); ++i) results_[i].title = campaign_.levels[i].title;
    index_ = std::min(results_.size(), count() - 1);
}

LevelResult CampaignProgress::totals() const {
    LevelResult sum;
    sum.title = campaign_.name;
    for (const LevelResult& r : results_) {
        sum.seconds += r.seconds;
        sum.robots_killed += r.robots_killed;
        sum.robots_total += r.robots_total;
        sum.shots += r.shots;
        sum.hits += r.hits;
    }
    return sum;
}

} // namespace ks::runtime
