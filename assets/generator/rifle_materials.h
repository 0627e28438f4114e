#pragma once
// The rifle's texture recipes (two paints, a polymer and a decal atlas) and its decal plates.
#include "material_builder.h"
#include "shapes.h"
#include "text.h"

namespace ks::assetgen {

// A tiling enamel of colour `paint` (mottled toward `paint_light`), chipped and scratched through to steel.
MaterialMaps rifle_paint(Color paint, Color paint_light, std::uint32_t seed);
// Dark stippled polymer (grip, magazine, butt).
MaterialMaps rifle_polymer();
// The markings atlas: 512 x 256, four 512 x 64 rows (0 maker's mark, 1 fire selector, 2 caution, 3 serial).
Image rifle_decals(const Font& font);
// A thin box whose faces show one row of the atlas; its +-X faces read left to right from either side.
Mesh rifle_decal_plate(vec3 size, int row);

} // namespace ks::assetgen
