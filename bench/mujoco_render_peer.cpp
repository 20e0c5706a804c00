// MuJoCo 2.2's off-screen renderer as the render-speed peer of tumble (issue "Pictures", item 6):
// a unit box resting on a plane, a directional light with its shadow map, 1280 × 720 through
// OSMesa on the same llvmpipe, as bench/scenes/peer_box.toml draws it in tumble. Prints MuJoCo's
// frames per second for drawing and reading back a frame (mjr_render + mjr_readPixels, the work of
// tumble's render stage) and writes its last frame as a PNG. scripts/render-peer runs it beside
// tumble in one run. MuJoCo is linked here only, never into a tumble library.
//
//   build/mujoco_render_peer [--frames N] [--png FILE] [--samples S] [--shadow N]
// --samples: MuJoCo's offsamples (multisampling, default 4, its own default); --shadow: its shadow
// map's size (default 4096, its own default).
#include <GL/osmesa.h>
#include <mujoco/mujoco.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "io/png_io.hpp"

namespace {

constexpr int kWidth = 1280, kHeight = 720;

// z up (MuJoCo's): the box's centre 0.5 m above the plane, as tumble's cube at y = 0.5. The light
// comes from tumble's default key-light direction (0.25, -1.2, -0.75), turned from y up to z
// up; by default 4× MSAA and a 4096² shadow map, MuJoCo's own defaults.
const char* kModel = R"(<mujoco>
  <visual>
    <global offwidth="1280" offheight="720" fovy="40"/>
    <quality shadowsize="%SHADOW%" offsamples="%SAMPLES%"/>
    <headlight ambient="0.25 0.25 0.25" diffuse="0.2 0.2 0.2"/>
  </visual>
  <worldbody>
    <light directional="true" castshadow="true" pos="-0.7 -2.1 3.4" dir="0.25 0.75 -1.2"
           diffuse="0.8 0.8 0.8"/>
    <geom type="plane" size="6 6 0.1" rgba="0.86 0.86 0.84 1"/>
    <body pos="0 0 0.5">
      <freejoint/>
      <geom type="box" size="0.5 0.5 0.5" rgba="0.96 0.55 0.2 1"/>
    </body>
  </worldbody>
</mujoco>)";

}  // namespace

int main(int argc, char** argv) {
  int frames = 300;
  std::string png = "mujoco_peer.png";
  std::string samples = "4", shadow = "4096";
  for (int i = 1; i + 1 < argc; i += 2) {
    if (std::strcmp(argv[i], "--frames") == 0) frames = std::atoi(argv[i + 1]);
    if (std::strcmp(argv[i], "--png") == 0) png = argv[i + 1];
    if (std::strcmp(argv[i], "--samples") == 0) samples = argv[i + 1];
    if (std::strcmp(argv[i], "--shadow") == 0) shadow = argv[i + 1];
  }
  std::string xml = kModel;
  xml.replace(xml.find("%SHADOW%"), 8, shadow);
  xml.replace(xml.find("%SAMPLES%"), 9, samples);
  // A compatibility-profile context: MuJoCo 2.2 draws with fixed-function OpenGL.
  OSMesaContext context = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 8, nullptr);
  std::vector<unsigned char> buffer(static_cast<std::size_t>(kWidth) * kHeight * 4);
  if (!context || !OSMesaMakeCurrent(context, buffer.data(), GL_UNSIGNED_BYTE, kWidth, kHeight)) {
    std::fprintf(stderr, "mujoco_render_peer: no OSMesa context\n");
    return 2;
  }
  mjVFS vfs;
  mj_defaultVFS(&vfs);
  const int size = static_cast<int>(xml.size());
  mj_makeEmptyFileVFS(&vfs, "box.xml", size);
  std::memcpy(vfs.filedata[mj_findFileVFS(&vfs, "box.xml")], xml.data(), xml.size());
  char error[1000] = "";
  mjModel* model = mj_loadXML("box.xml", &vfs, error, sizeof error);
  mj_deleteVFS(&vfs);
  if (!model) {
    std::fprintf(stderr, "mujoco_render_peer: %s\n", error);
    return 2;
  }
  mjData* data = mj_makeData(model);
  mjvCamera camera;
  mjvOption option;
  mjvScene scene;
  mjrContext render;
  mjv_defaultCamera(&camera);
  mjv_defaultOption(&option);
  mjv_defaultScene(&scene);
  mjr_defaultContext(&render);
  mjv_makeScene(model, &scene, 100);
  mjr_makeContext(model, &render, mjFONTSCALE_100);
  mjr_setBuffer(mjFB_OFFSCREEN, &render);
  // tumble's dropped-cube camera, (4, 3, 7) looking at (0, 1, 0) in y up, which is (4, -7, 3)
  // looking at (0, 0, 1) in z up: 8.3 m away, looking along (-4, 7, -2), 13.9° down.
  camera.type = mjCAMERA_FREE;
  camera.lookat[0] = 0.0, camera.lookat[1] = 0.0, camera.lookat[2] = 1.0;
  camera.distance = std::sqrt(4.0 * 4.0 + 2.0 * 2.0 + 7.0 * 7.0);
  camera.azimuth = std::atan2(7.0, -4.0) * 180.0 / M_PI;
  camera.elevation = -std::asin(2.0 / camera.distance) * 180.0 / M_PI;
  const mjrRect viewport = mjr_maxViewport(&render);
  std::vector<unsigned char> rgb(static_cast<std::size_t>(kWidth) * kHeight * 3);
  // The first frame compiles shaders and fills the caches: not timed.
  mj_forward(model, data);
  mjv_updateScene(model, data, &option, nullptr, &camera, mjCAT_ALL, &scene);
  mjr_render(viewport, &scene, &render);
  mjr_readPixels(rgb.data(), nullptr, viewport, &render);
  const auto start = std::chrono::steady_clock::now();
  for (int k = 0; k < frames; ++k) {
    mj_step(model, data);  // the box at rest on the plane, as in tumble's frames
    mjv_updateScene(model, data, &option, nullptr, &camera, mjCAT_ALL, &scene);
    mjr_render(viewport, &scene, &render);
    mjr_readPixels(rgb.data(), nullptr, viewport, &render);
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf(
      "mujoco %s (offsamples %s, shadowsize %s): %d frames of %dx%d in %.3f s: %.1f "
      "frames/s (%s)\n",
      mj_versionString(), samples.c_str(), shadow.c_str(), frames, viewport.width, viewport.height,
      seconds, frames / seconds, reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
  // Rows come bottom up.
  tumble::io::Image image(viewport.width, viewport.height);
  const std::size_t row = static_cast<std::size_t>(viewport.width) * 3;
  for (int y = 0; y < viewport.height; ++y) {
    std::memcpy(image.rgb.data() + row * y, rgb.data() + row * (viewport.height - 1 - y), row);
  }
  const tumble::Result<void> written = tumble::io::write_png(png, image);
  if (!written) std::fprintf(stderr, "mujoco_render_peer: %s\n", written.error().c_str());
  mjr_freeContext(&render);
  mjv_freeScene(&scene);
  mj_deleteData(data);
  mj_deleteModel(model);
  OSMesaDestroyContext(context);
  return written ? 0 : 2;
}
