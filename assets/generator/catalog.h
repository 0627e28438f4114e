#pragma once
// Every asset the generator makes, by name. `--only NAME` picks one; the default makes them all. The
// sounds (sounds.h) are one recipe each, named as their files.
#include "output.h"

#include <functional>
#include <string>
#include <vector>

namespace ks::assetgen {

struct Recipe {
    std::string name;
    std::string what;
    std::function<Result<void>(Output& out)> make;
};

const std::vector<Recipe>& catalog();

// The recipes (one file each).
Result<void> make_surface_concrete(Output& out);
Result<void> make_surface_wood(Output& out);
Result<void> make_surface_tiles(Output& out);
Result<void> make_surface_ceiling(Output& out);
Result<void> make_surface_metal(Output& out);
Result<void> make_surface_dojo_floor(Output& out);
Result<void> make_particles(Output& out);
Result<void> make_robot(Output& out);
Result<void> make_rifle(Output& out);
Result<void> make_door(Output& out);
Result<void> make_floor_light(Output& out);
Result<void> make_top_light(Output& out);
Result<void> make_control_panel(Output& out);
Result<void> make_gas_cylinder(Output& out);
Result<void> make_pickups(Output& out);
Result<void> make_archive_shelf(Output& out);
Result<void> make_icons(Output& out);

} // namespace ks::assetgen
