#include "diff/diff_outputs.hpp"

#include <algorithm>

#include "diff/diff_text.hpp"

namespace tumble::diff {
namespace {

std::string test_case(const std::string& name, const std::string& failure) {
  std::string text =
      "    <testcase classname=\"tumble.diff\" name=\"" + markup_text(name) + "\" time=\"0\"";
  if (failure.empty()) return text + "/>\n";
  return text + ">\n      <failure type=\"mismatch\" message=\"" + markup_text(failure) + "\">" +
         markup_text(failure) + "</failure>\n    </testcase>\n";
}

}  // namespace

// One test case per compared frame, and one for the frame count when the inputs' differ, in the
// layout Jenkins, GitLab and GitHub's test reporters read (testsuites > testsuite > testcase).
Result<void> write_diff_junit(const std::string& path, const DiffSubject& subject,
                              const SequenceDiff& diff) {
  std::string cases;
  std::size_t tests = 0, failures = 0;
  for (const FrameOutcome& frame : diff.frames) {
    ++tests;
    failures += !frame.match;
    cases += test_case(frame.name, frame.match ? "" : outcome_text(frame, subject.criteria));
  }
  if (diff.first_count != diff.second_count) {
    ++tests;
    ++failures;
    cases += test_case("frame count", "A has " + std::to_string(diff.first_count) +
                                          " frames, B has " + std::to_string(diff.second_count));
  }
  const std::string counts =
      "tests=\"" + std::to_string(tests) + "\" failures=\"" + std::to_string(failures) + "\"";
  const std::string suite = markup_text(subject.first_path + " vs " + subject.second_path);
  const std::string text =
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"tumble diff\" " + counts +
      " errors=\"0\">\n  <testsuite name=\"" + suite + "\" " + counts +
      " errors=\"0\" skipped=\"0\" time=\"0\">\n    <properties>\n      <property "
      "name=\"criteria\" value=\"" +
      markup_text(criteria_text(subject.criteria)) + "\"/>\n" +
      (diff.adaptation.empty() ? std::string()
                               : "      <property name=\"adaptation\" value=\"" +
                                     markup_text(diff.adaptation) + "\"/>\n") +
      "    </properties>\n" + cases + "  </testsuite>\n</testsuites>\n";
  return write_text_atomically(path, text);
}

}  // namespace tumble::diff
