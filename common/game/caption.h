#pragma once
// The HUD caption ("Press E to open the door") with the reference's owner rule (seed doc, HUD): the caption
// has an owner, set whenever its text changes; unless the owner changes, only the owner may hide it. So a
// second object showing its text takes the caption over, and the first object leaving reach afterwards
// cannot hide the second one's text.
#include <string>
#include <string_view>

namespace ks::game {

class Caption {
  public:
    static constexpr int kNoOwner = -1;
    // Shows `text` owned by `owner`; returns whether anything visible changed.
    bool show(std::string_view text, int owner);
    // Hides the caption if `owner` owns it; returns whether it was hidden by this call.
    bool hide(int owner);
    bool visible() const { return visible_; }
    const std::string& text() const { return text_; }
    int owner() const { return owner_; }

  private:
    std::string text_;
    int owner_ = kNoOwner;
    bool visible_ = false;
};

} // namespace ks::game
