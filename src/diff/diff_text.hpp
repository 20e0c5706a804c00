// The words and numbers `tumble diff` prints for a frame: on standard output, in the JUnit
// failure messages and in the HTML report alike.
#pragma once

#include <cstdint>
#include <string>

#include "diff/diff_run.hpp"
#include "diff/image_diff.hpp"

namespace tumble::diff {

// Three significant digits, never in exponent notation: 8.33%, 0.0244%, 0.000301%.
std::string percent_text(std::int64_t part, std::int64_t whole);

// The figures of one compared frame in the metric's terms. For max without anti-aliasing
// ignored: "1 of 12 pixels differ (8.33%), largest channel difference 10, RMS 1.667".
std::string figures_text(const diff::FrameFigures& figures, const diff::FrameCriteria& criteria);

// "match" or "mismatch", then the problem or the figures.
std::string outcome_text(const FrameOutcome& outcome, const diff::FrameCriteria& criteria);

// The metric with its threshold and unit: "perceptual, threshold 0.1 (YIQ distance 0-1)".
std::string criteria_text(const diff::FrameCriteria& criteria);

// The sequence's verdict: "mismatch: 3 of 100 frames differ; A has 100 frames, B has 98".
std::string verdict_text(const SequenceDiff& diff);

// Text for XML or HTML, attribute or element: markup characters as entities, and control
// characters XML 1.0 cannot hold at all as '?'.
std::string markup_text(const std::string& text);

}  // namespace tumble::diff
