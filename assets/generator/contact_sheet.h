#pragma once
// A debugging aid: every texture written in this run, shrunk into one labelled grid PNG.
#include "output.h"

namespace ks::assetgen {

Result<void> write_contact_sheet(const Output& out, const std::filesystem::path& file);

} // namespace ks::assetgen
