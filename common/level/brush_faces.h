#pragma once
// A brush entity's faces in the level file: "faces": [{"plane": [nx, ny, nz, d], "material": "concrete",
// "offset": [u, v], "scale": [u, v], "rotation": degrees}, ...], planes in the entity's frame, numbers in
// their shortest round-trip form (docs/level-format.md, "Brushes"). The brush module checks the planes;
// its refusals ("faces[3].plane.normal") are reported at the file's own places ("props.faces[3].plane").
#include "level/diagnostics.h"

#include <nlohmann/json.hpp>

#include <string>

namespace ks::level {

// Reads the faces at `path` into `out` (left alone on any problem, each reported to the sink).
bool read_brush_faces(const nlohmann::ordered_json& value, const std::string& path, DiagnosticSink& sink,
                      brush::Brush& out);

// The faces as the file writes them.
nlohmann::ordered_json brush_faces_json(const brush::Brush& brush);

// The brush module's error path ("faces", "faces[3]", "faces[3].plane.distance", "faces[1].scale.y") as the
// file's path below `faces_path` ("...props.faces[3].plane[3]", "...props.faces[1].scale[1]").
std::string brush_error_path(const std::string& faces_path, const std::string& brush_path);

// The empty materials of a brush (an error, like an empty texture), at `faces_path`'s faces.
void check_brush_materials(const brush::Brush& brush, const std::string& faces_path, DiagnosticSink& sink);

} // namespace ks::level
