// The video formats a render writes, as plain data: named in scenes ([output] formats), on the
// command line (--format) and by the encoder (io/video_encoder.hpp), so that none of them
// includes another.
#pragma once

#include <optional>
#include <string_view>

namespace tumble::common {

enum class VideoFormat { mp4, webm, gif };

// [output] formats and --format take the videos' names and "gltf": the motion as a glTF 2.0
// binary, <scene>.glb (io/glb_writer.hpp, job/gltf_scene.hpp). It is no video (no encoder, no
// pixels: it is written from the bodies' poses), so it is not a VideoFormat, [output] video =
// false and --no-video leave it on, and it has no rule of size or alpha.
inline constexpr std::string_view kGltfFormatName = "gltf";
inline constexpr std::string_view kGltfExtension = "glb";  // binary glTF: <scene>.glb
// And "html": the motion replayed in a browser, <scene>.html, one self-contained page holding
// the glTF, three.js and the overlays drawn in the scene (job/html_replay.hpp). No video either,
// for the same reasons.
inline constexpr std::string_view kHtmlFormatName = "html";
inline constexpr std::string_view kHtmlExtension = "html";  // <scene>.html
// Every name of [output] formats and --format, for messages.
inline constexpr const char* kFormatNames = "\"mp4\", \"webm\", \"gif\", \"gltf\" or \"html\"";

inline constexpr VideoFormat kAllVideoFormats[] = {VideoFormat::mp4, VideoFormat::webm,
                                                   VideoFormat::gif};

// "mp4", "webm", "gif": the name in scenes and on the command line, and the file extension.
constexpr const char* video_format_name(VideoFormat format) {
  switch (format) {
    case VideoFormat::mp4:
      return "mp4";
    case VideoFormat::webm:
      return "webm";
    case VideoFormat::gif:
      return "gif";
  }
  return "?";
}

// The format named `name`, or nothing.
constexpr std::optional<VideoFormat> video_format_named(std::string_view name) {
  for (const VideoFormat format : kAllVideoFormats) {
    if (name == video_format_name(format)) return format;
  }
  return std::nullopt;
}

// Whether the format stores colour in 4:2:0 (one chroma sample per 2×2 pixels), so that its
// picture must have an even width and height. A GIF's palette indices have no chroma planes.
constexpr bool needs_even_size(VideoFormat format) {
  return format != VideoFormat::gif;
}

// Whether the format can carry an alpha channel as tumble writes it (VP9 yuva420p in WebM).
constexpr bool carries_alpha(VideoFormat format) {
  return format == VideoFormat::webm;
}

// Whether a render of part of the frames writes this format as a segment that `tumble join` joins
// by stream copy (H.264 in MP4, VP9 in WebM: each segment starts with a key frame). A GIF's
// palette is chosen for its own frames, so parts of one would not make the whole's GIF.
constexpr bool joins_in_segments(VideoFormat format) {
  return format != VideoFormat::gif;
}

// How a GIF's frames are mapped onto its palette ([output] gif_dither): not at all (flat areas,
// bands in gradients), ordered (a Bayer pattern that stays put from frame to frame) or by error
// diffusion (Floyd-Steinberg: finer, but its pattern crawls wherever anything moves).
enum class GifDither { none, bayer, floyd_steinberg };

inline constexpr GifDither kAllGifDithers[] = {GifDither::none, GifDither::bayer,
                                               GifDither::floyd_steinberg};

// "none", "bayer", "floyd_steinberg": the name in scenes, and libavfilter paletteuse's.
constexpr const char* gif_dither_name(GifDither dither) {
  switch (dither) {
    case GifDither::none:
      return "none";
    case GifDither::bayer:
      return "bayer";
    case GifDither::floyd_steinberg:
      return "floyd_steinberg";
  }
  return "?";
}

inline constexpr int kMinGifColors = 2;    // GIF's smallest palette (1 bit)
inline constexpr int kMaxGifColors = 256;  // and its largest (8 bits)
inline constexpr int kMaxGifFps = 50;      // 2 cs per frame: browsers slow anything faster

}  // namespace tumble::common
