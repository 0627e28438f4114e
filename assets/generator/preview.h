#pragma once
// A debugging aid until the renderer can show models: flat-lit orthographic software renders of every
// model written in this run (side, front, three-quarter from above and from behind-below), textured with the
// base colour maps generated in the same run.
#include "output.h"

namespace ks::assetgen {

// Each view is `view_size` pixels square; the four sit side by side in <folder>/<model>.png.
Result<void> write_previews(const Output& out, const std::filesystem::path& folder, int view_size = 360);

} // namespace ks::assetgen
