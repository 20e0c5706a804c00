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

// Writes `text` to `path` through io::AtomicFile; the error names the file.
Result<void> write_text_atomically(const std::string& path, const std::string& text);

// Each error names the file that could not be written.
Result<void> write_diff_json(const std::string& path, const DiffSubject& subject,
                             const SequenceDiff& diff);
Result<void> write_diff_junit(const std::string& path, const DiffSubject& subject,
                              const SequenceDiff& diff);
// `folder`/index.html with a summary table of every frame, and for each kept (failing) frame the
// expected, actual and difference images side by side (PNGs beside the page: no network, no
// script). The folder is staged and swapped into place whole.
Result<void> write_diff_report(const std::string& folder, const DiffSubject& subject,
                               const SequenceDiff& diff);

}  // namespace tumble::diff
