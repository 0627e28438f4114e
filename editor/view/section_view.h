#pragma once
// The axis views' section (View > Section at the selection): in the front and side views the outer walls
// stand between the camera and the rooms, and hide them and the selection's outline. With the section on,
// every entity wholly nearer the camera than the selection's nearest point is left out of the picture and
// of picking, so the room around the selection shows as a cut through the level. Window-free: tested with a
// ViewCamera (tests/editor/test_quad_view.cpp).
#include "model/editor.h"
#include "view/view_camera.h"

#include <cstdint>
#include <optional>

namespace ks::editor {

// Where the section cuts: along the view direction, the selection's nearest depth.
struct SectionCut {
    Vec3 direction{0.0f}; // the view's, unit: from the camera into the picture
    float depth = 0.0f;   // dot(direction, p) of the selection's point nearest the camera
    bool operator==(const SectionCut&) const = default;
};

// The cut for the front and side views with entities selected; none in the perspective and top views
// (from above only ceilings hide the rooms, and they have their own switch) or with nothing selected.
std::optional<SectionCut> section_cut(const Editor& editor, const ViewCamera& view);
// The entity lies wholly in front of the cut (between the camera and the selection). Selected entities
// never are.
bool in_front_of_cut(const SectionCut& cut, const level::Entity& entity);
// Changes whenever the cut does (the picture is rebuilt then).
std::uint64_t section_key(const std::optional<SectionCut>& cut);

} // namespace ks::editor
