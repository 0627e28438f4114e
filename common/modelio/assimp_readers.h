#pragma once
// Which of assimp's readers may read a file. Assimp offers a file its extension's reader declines to every
// other reader that recognises a few words in it: a ".gltf" holding "GeometryNode" went to the OpenGEX
// reader, which read past the end of its buffer (a fuzz finding,
// tests/data/fuzz/fuzz_model_import/crash-cb2d9cce…). So a model is read only by the readers of its own
// extension, and is refused, with assimp's message, when they cannot read it.
#include <assimp/Importer.hpp>

#include <filesystem>

namespace ks::modelio {

// Removes from `importer` every reader that does not list `file`'s extension (case-insensitive). With no
// extension, or one no reader lists, no reader is left and reading fails with a clear message.
void keep_extension_readers(Assimp::Importer& importer, const std::filesystem::path& file);

} // namespace ks::modelio
