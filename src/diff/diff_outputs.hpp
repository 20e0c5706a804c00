// What `tumble diff` writes besides its summary lines: a JSON file with every figure, a JUnit XML
// file with one test case per frame (CI systems show the failing frames natively), and an HTML
// report folder. Each appears whole or not at all.
#pragma once

#include <string>

#include "common/result.hpp"

#include "diff/diff_run.hpp"
#include "diff/image_diff.hpp"

namespace tumble::diff {

// What was compared with what, and how: the heading of every output.
struct DiffSubject {
  std::string first_path;   // A, the expected frames
  std::string second_path;  // B, the actual frames
  diff::FrameCriteria criteria;
};

// The html replay of a side of the comparison: the one *.html file of a folder (a render's
// <name>.html, [output] formats = ["html"]); "" for a file, or a folder with none or several.
std::string replay_of(const std::string& side);

// Writes `text` to `path` through io::AtomicFile; the error names the file.
Result<void> write_text_atomically(const std::string& path, const std::string& text);

// Each error names the file that could not be written.
Result<void> write_diff_json(const std::string& path, const DiffSubject& subject,
                             const SequenceDiff& diff);
Result<void> write_diff_junit(const std::string& path, const DiffSubject& subject,
                              const SequenceDiff& diff);
// `folder`/index.html with a summary table of every frame, and for each kept (failing) frame the
// expected, actual and difference images side by side (PNGs beside the page: no network, no
// script). When both sides have an html replay (replay_of), each is copied beside the page
// (replay-a.html, replay-b.html) and shown in a frame of it, side by side: the pages run their
// own script, self-contained as tumble render writes them. The folder is staged and swapped into
// place whole.
Result<void> write_diff_report(const std::string& folder, const DiffSubject& subject,
                               const SequenceDiff& diff);

}  // namespace tumble::diff
