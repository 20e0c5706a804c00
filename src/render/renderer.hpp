// Draws a FrameView into an image: shadow pass from the key light, then the ground without
// shadows (a kept copy while the camera stays, ground_cache.hpp), the boxes (one instanced draw),
// the ground's shadows, the quads seen from their front and last the quads seen from their back
// (translucent). All into a framebuffer of the renderer's own (multisampled when the settings
// ask for samples), read back from it (through the edge filter by default). Text last, over
// everything, left alone by the edge filter (text_layer.hpp).
#pragma once

#include <memory>
#include <string>

#include "common/result.hpp"
#include "io/image.hpp"
#include "render/font.hpp"
#include "render/frame.hpp"

namespace tumble::render {

class Renderer {
 public:
  // Creates the off-screen context (current on the calling thread from then on), loads the
  // shaders from `shader_directory` and the GPU buffers, and the font when the settings name one.
  // An error gives a file name and compiler log for shader errors, the family for a font
  // fontconfig does not have.
  static Result<std::unique_ptr<Renderer>> create(const RenderSettings& settings,
                                                  const std::string& shader_directory);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Draws one frame into `out` (resized to the settings' width and height). Must be called on
  // the thread that created the renderer; several renderers of one back end on a thread may draw
  // in turn (each makes its context current again).
  void draw(const FrameView& view, io::Image& out);

  // The GL implementation in use and the back end that made its context, for --verbose.
  std::string description() const;
  // The back end that made the context, and its device (OffscreenContext::device).
  common::Backend backend() const;
  std::string device() const;
  // The GL implementation alone (GL_RENDERER and GL_VERSION): what decides the pixels, as the
  // back ends draw the same bytes. On the thread that created the renderer.
  std::string opengl() const;

  // The font FrameView::texts are drawn in, to warn about the characters it lacks
  // (Font::missing_characters); null when the settings name no font.
  const Font* font() const;

  struct Resources;  // GL objects, defined in renderer.cpp

 private:
  explicit Renderer(std::unique_ptr<Resources> resources);
  // One picture of `view` with these boxes, read back into `out`; then, unless it is
  // `one_of_several` pictures of a motion-blurred frame, finish_picture.
  void draw_picture(const FrameView& view, const std::vector<Box>& boxes, io::Image& out,
                    bool one_of_several);
  // The layers drawn over the picture read back: panels and strokes, texts, straight alpha.
  void finish_picture(const FrameView& view, io::Image& out);
  std::unique_ptr<Resources> resources_;
};

}  // namespace tumble::render
