#include "render/app_shell.h"

#include <epoxy/gl.h>
#include <stb_image_write.h>

#include <vector>

namespace ks::render {

Result<void> save_framebuffer_png(const std::string& path, int width, int height) {
    if (width <= 0 || height <= 0) return Error("empty framebuffer", Location{path});
    std::vector<unsigned char> pixels(static_cast<size_t>(width) * height * 3);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadBuffer(GL_BACK);
    glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, pixels.data());
    // GL rows run bottom-up; PNG rows top-down: write with a negative stride from the last row.
    const int stride = width * 3;
    const unsigned char* last_row = pixels.data() + static_cast<size_t>(height - 1) * stride;
    if (!stbi_write_png(path.c_str(), width, height, 3, last_row, -stride))
        return Error("cannot write PNG", Location{path}, "check that the folder exists and is writable");
    return ok();
}

} // namespace ks::render
