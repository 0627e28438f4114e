#pragma once
// Shared by the anim tests: the shipped robot clip file, loaded once.
#include "anim/clip_io.h"
#include "core/paths.h"

#include <doctest/doctest.h>

namespace ks::anim::test {

inline const AnimationLibrary& robot_library() {
    static const AnimationLibrary library = [] {
        auto loaded = load_animation_library(paths::asset("animations/robot.json"));
        if (!loaded) FAIL(loaded.error().str());
        return std::move(loaded).value();
    }();
    return library;
}

} // namespace ks::anim::test
