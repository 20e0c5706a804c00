#include "diff/diff_outputs.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <system_error>

#include "diff/diff_text.hpp"
#include "io/png_io.hpp"
#include "io/staged_directory.hpp"

namespace tumble::diff {
namespace {

constexpr const char* kStyle =
    "body{font-family:sans-serif;margin:1.5em;color:#222}"
    "table{border-collapse:collapse}td,th{border:1px solid #bbb;padding:2px 6px;"
    "text-align:right}td.name,th.name{text-align:left}tr.fail td{background:#fdd}"
    ".row{display:flex;gap:8px;flex-wrap:wrap}figure{margin:0}"
    "img{max-width:32vw;image-rendering:pixelated;border:1px solid #888}"
    "iframe{width:calc(50vw - 2.5em);height:calc((50vw - 2.5em) * 9 / 16 + 4.5em);"
    "border:1px solid #888}";

std::string number_cell(const char* format, double value) {
  if (std::isinf(value)) return "<td>inf</td>";
  char text[64];
  std::snprintf(text, sizeof text, format, value);
  return std::string("<td>") + text + "</td>";
}

std::string table_row(const FrameOutcome& frame) {
  std::string row = std::string("<tr") + (frame.match ? "" : " class=\"fail\"") + "><td>" +
                    std::to_string(frame.index) + "</td><td class=\"name\">" +
                    markup_text(frame.name) + "</td><td class=\"name\">" +
                    markup_text(frame.match             ? "match"
                                : frame.problem.empty() ? "mismatch"
                                                        : frame.problem) +
                    "</td>";
  if (!frame.figures) return row + "<td colspan=\"7\"></td></tr>\n";
  const diff::FrameFigures& f = *frame.figures;
  row += "<td>" + std::to_string(f.differing_pixels) + "</td><td>" +
         std::to_string(f.antialiased_pixels) + "</td><td>" +
         (f.quantised_pixels ? std::to_string(*f.quantised_pixels) : std::string()) + "</td><td>" +
         std::to_string(f.max_channel_difference) + "</td>" + number_cell("%.4g", f.rms) +
         number_cell("%.2f", f.psnr) +
         (f.ssim ? number_cell("%.5f", *f.ssim) : std::string("<td></td>"));
  return row + "</tr>\n";
}

std::string summary_table(const SequenceDiff& diff) {
  std::string table =
      "<table>\n<tr><th>#</th><th class=\"name\">frame</th><th class=\"name\">result</th>"
      "<th>differing pixels</th><th>anti-aliased</th><th>within quantisation</th>"
      "<th>largest channel difference</th>"
      "<th>RMS</th><th>PSNR (dB)</th><th>SSIM</th></tr>\n";
  for (const FrameOutcome& frame : diff.frames) table += table_row(frame);
  return table + "</table>\n";
}

std::string image_name(const KeptFrame& frame, const char* role) {
  return "frame-" + std::to_string(frame.index) + "-" + role + ".png";
}

std::string figure(const std::string& file, const std::string& caption) {
  return "<figure><img src=\"" + file + "\" alt=\"" + caption + "\"><figcaption>" + caption +
         "</figcaption></figure>";
}

// The kept frame's three PNGs into `folder`, and its section of the page.
Result<std::string> kept_section(const KeptFrame& kept, const SequenceDiff& diff,
                                 const diff::FrameCriteria& criteria, const std::string& folder) {
  const io::Image* images[] = {&kept.first, &kept.second, &kept.difference};
  const char* roles[] = {"expected", "actual", "difference"};
  for (int n = 0; n < 3; ++n) {
    const Result<void> written =
        io::write_png(folder + "/" + image_name(kept, roles[n]), *images[n]);
    if (!written) return Error{written.error()};
  }
  const FrameOutcome* outcome = nullptr;
  for (const FrameOutcome& frame : diff.frames) {
    if (frame.index == kept.index) outcome = &frame;
  }
  const std::string title = outcome ? outcome->name : std::to_string(kept.index);
  return "<section>\n<h3>" + markup_text(title) + "</h3>\n<p>" +
         (outcome ? markup_text(outcome_text(*outcome, criteria)) : "") +
         "</p>\n<div class=\"row\">" + figure(image_name(kept, "expected"), "expected (A)") +
         figure(image_name(kept, "actual"), "actual (B)") +
         figure(image_name(kept, "difference"), "difference") + "</div>\n</section>\n";
}

// The replays of both sides copied beside the page (replay-a.html, replay-b.html), and their
// section; "" when a side has none.
Result<std::string> replays_section(const DiffSubject& subject, const std::string& folder) {
  const std::string sides[] = {replay_of(subject.first_path), replay_of(subject.second_path)};
  if (sides[0].empty() || sides[1].empty()) return std::string();
  const char* names[] = {"replay-a.html", "replay-b.html"};
  const std::string captions[] = {"expected (A): " + subject.first_path,
                                  "actual (B): " + subject.second_path};
  std::string row;
  for (int n = 0; n < 2; ++n) {
    std::error_code error;
    std::filesystem::copy_file(sides[n], folder + "/" + names[n], error);
    if (error)
      return Error{folder + "/" + names[n] + ": cannot copy " + sides[n] + ": " + error.message()};
    row += std::string("<figure><iframe src=\"") + names[n] + "\" title=\"" +
           markup_text(captions[n]) + "\"></iframe><figcaption>" + markup_text(captions[n]) +
           "</figcaption></figure>";
  }
  return "<h2>Replays</h2>\n<p>Each side's html replay (tumble render's [output] formats = "
         "[\"html\"]): play, scrub and turn each on its own.</p>\n<div class=\"row\">" +
         row + "</div>\n";
}

}  // namespace

std::string replay_of(const std::string& side) {
  namespace fs = std::filesystem;
  std::error_code error;
  if (!fs::is_directory(side, error)) return {};
  std::string found;
  for (const fs::directory_entry& entry : fs::directory_iterator(side, error)) {
    if (!entry.is_regular_file(error) || entry.path().extension() != ".html") continue;
    if (!found.empty()) return {};  // two pages: neither is known to be the replay
    found = entry.path().string();
  }
  return found;
}

Result<void> write_diff_report(const std::string& folder, const DiffSubject& subject,
                               const SequenceDiff& diff) {
  Result<io::StagedDirectory> staged = io::StagedDirectory::create(folder);
  if (!staged) return Error{staged.error()};
  const diff::FrameCriteria& criteria = subject.criteria;
  std::string sections;
  for (const KeptFrame& kept : diff.worst) {
    const Result<std::string> section = kept_section(kept, diff, criteria, staged->path());
    if (!section) return Error{section.error()};
    sections += *section;
  }
  const Result<std::string> replays = replays_section(subject, staged->path());
  if (!replays) return Error{replays.error()};
  const std::string heading = markup_text(subject.first_path + " vs " + subject.second_path);
  const std::string page =
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>tumble "
      "diff: " +
      heading + "</title>\n<style>" + kStyle + "</style>\n</head>\n<body>\n<h1>tumble diff</h1>\n" +
      "<p>A (expected): " + markup_text(subject.first_path) +
      "<br>B (actual): " + markup_text(subject.second_path) + "<br>" +
      markup_text(criteria_text(criteria)) + "</p>\n<p><strong>" + markup_text(verdict_text(diff)) +
      "</strong></p>\n" +
      (diff.adaptation.empty() ? std::string()
                               : "<p>Note: " + markup_text(diff.adaptation) + "</p>\n") +
      (diff.worst.empty() ? std::string()
                          : "<h2>Failing frames (the worst " + std::to_string(diff.worst.size()) +
                                ")</h2>\n" + sections) +
      *replays + "<h2>Every frame</h2>\n" + summary_table(diff) + "</body>\n</html>\n";
  if (Result<void> written = write_text_atomically(staged->path() + "/index.html", page);
      !written) {
    return written;
  }
  return staged->commit();
}

}  // namespace tumble::diff
