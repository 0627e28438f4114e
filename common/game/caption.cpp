#include "game/caption.h"

namespace ks::game {

bool Caption::show(const std::string& text, int owner) {
    const bool changed = !visible_ || text != text_ || owner != owner_;
    text_ = text;
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
