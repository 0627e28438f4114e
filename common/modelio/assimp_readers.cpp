#include "modelio/assimp_readers.h"

#include <assimp/BaseImporter.h>

#include <algorithm>
#include <cctype>
#include <set>
#include <string>
#include <vector>

namespace ks::modelio {

void keep_extension_readers(Assimp::Importer& importer, const std::filesystem::path& file) {
    std::string extension = file.extension().string();
    if (!extension.empty()) extension.erase(0, 1);
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    std::vector<Assimp::BaseImporter*> others;
    for (std::size_t i = 0; i < importer.GetImporterCount(); ++i) {
        Assimp::BaseImporter* reader = importer.GetImporter(i);
        std::set<std::string> listed;
        reader->GetExtensionList(listed);
        if (extension.empty() || listed.count(extension) == 0) others.push_back(reader);
    }
    // UnregisterLoader hands the reader back without deleting it (the importer deletes only those it holds).
    for (Assimp::BaseImporter* reader : others)
        if (importer.UnregisterLoader(reader) == aiReturn_SUCCESS) delete reader;
}

} // namespace ks::modelio
