#pragma once
// The quick fixes of a model entity's problems that level validation reports (level_checks.cpp's
// check_model; docs/models.md "When something is wrong"): the inspector's button for each.
#include "level/diagnostics.h"
#include "model/quick_fix.h"

namespace ks::editor {

// For a diagnostic at a model entity's props: "Reset scale" (scale 1) for a placed size out of range, "Use
// box collision" for a hull or triangle mesh that cannot be made ("No collision" for a flat model, which has
// no box either), "Use NAME" for a file that is not there
// when a model in the Models tab's folders (model_library.h) has a close name. No fix otherwise (a corrupt
// file: export it again; the inspector's Models tab picks another file).
QuickFix model_quick_fix(const level::Entity& entity, const level::Diagnostic& diagnostic);

} // namespace ks::editor
