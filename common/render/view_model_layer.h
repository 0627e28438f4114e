#pragma once
// The first-person view model drawn at the target's full resolution into its own layer and blended over the
// finished scene: its edges stay smooth when the scene is drawn at a reduced resolution and scaled up, or
// without MSAA (the software rasterisers' default). One sample per pixel: the composite shader's silhouette
// filter blends the edges (llvmpipe's MSAA cost ~30 ms of CPU per frame for the rifle alone); 2/4/8 samples:
// a multisampled layer, resolved. Only the pixels of the view model's screen rectangle are cleared, drawn,
// resolved and blended.
#include "core/result.h"
#include "render/render_target.h"
#include "render/scene.h"
#include "render/shader_program.h"

#include <memory>
#include <vector>

namespace ks::render {

struct PixelRect {
    int x = 0, y = 0, width = 0, height = 0; // GL window coordinates (origin bottom left)
    bool empty() const { return width <= 0 || height <= 0; }
};

// The pixels that `instances` (camera-space placements) can cover under `projection` in a width x height
// target: the corners of each mesh's convex hull (GpuMesh::hull_corners) projected, widened by a pixel and a
// half for the antialiased rim. The rectangle is clipped to the target (empty when nothing lies in front of
// the camera); the hull is the projected corners' convex hull, widened, cut to that rectangle (window
// coordinates, counter-clockwise), empty when a corner lies behind the eye (then the rectangle is all there
// is). The composite draws the hull: for the rifle about three fifths of its rectangle (its bounding box's
// corners gave four fifths).
struct ScreenFootprint {
    PixelRect rect;
    std::vector<Vec2> hull;
};
// Fills `out`; its hull's storage is kept between calls, so a renderer that keeps one allocates nothing per
// frame.
void view_model_footprint(const std::vector<MeshInstance>& instances, const Mat4& projection, int width,
                          int height, ScreenFootprint& out);

class ViewModelLayer {
  public:
    ViewModelLayer();
    ~ViewModelLayer();
    ViewModelLayer(const ViewModelLayer&) = delete;
    ViewModelLayer& operator=(const ViewModelLayer&) = delete;

    // Built by the SceneRenderer's shader library.
    ShaderProgram& program() { return composite_; }
    ShaderProgram& mask_program() { return mask_; }
    // Binds the layer (width x height, `samples` per pixel; 1: single-sample with the edge filter) and clears
    // `rect` to transparent black, with the scissor left on it for the view model's draws. An error when the
    // driver cannot make the target.
    Result<void> begin(int width, int height, int samples, const PixelRect& rect);
    // Resolves `where.rect` of a multisampled layer (once per begin; composite calls it when not yet done).
    void resolve(const PixelRect& rect);
    // Writes the layer's opaque pixels inside `where` into `target_framebuffer`, colour and depth 0: drawn
    // before the scene, the scene is not shaded under them and they need no composite. Leaves the target
    // bound, depth test on with GL_LESS and writes on.
    void write_depth_mask(unsigned target_framebuffer, const ScreenFootprint& where);
    // Resolves `where.rect` and blends the pixels inside `where.hull` (the rectangle's when it has none) over
    // `target_framebuffer` (left bound, blending and scissor off). `masked`: write_depth_mask ran on this
    // target before the scene, so its depth is 0 exactly at the opaque pixels, which hold the layer's colour
    // already: only the others go through the edge filter (depth LESS).
    void composite(unsigned target_framebuffer, const ScreenFootprint& where, bool masked);

  private:
    void
    draw_footprint(const ScreenFootprint& where); // the hull (or rectangle) as a fan, in the bound target
    std::unique_ptr<RenderTarget> multisampled_;
    RenderTarget resolved_{{ColourStorage::Texture, 0}};
    ShaderProgram composite_, mask_;
    unsigned vao_ = 0, vertex_buffer_ = 0;
    std::vector<Vec2> fan_; // the composite's polygon in clip space, reused
    int width_ = 0, height_ = 0, samples_ = 1;
    bool resolved_this_frame_ = false;
};

} // namespace ks::render
