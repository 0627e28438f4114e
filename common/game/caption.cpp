#include "game/caption.h"

namespace ks::game {

bool Caption::show(std::string_view text, int owner) {
    const bool changed = !visible_ || text != text_ || owner != owner_;
    if (text != text_) text_.assign(text); // keeps its capacity: no allocation per step
    owner_ = owner;
    visible_ = true;
    return changed;
}

bool Caption::hide(int owner) {
    if (!visible_ || owner != owner_) return false;
    visible_ = false;
    return true;
}

} // namespace ks::game
