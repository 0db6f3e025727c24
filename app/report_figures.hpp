// The report's figures (scripts/figures.py), drawn by background interpreters as their inputs become final:
// the calibration's after kfit, the contact's by an interpreter started early that waits for a go on its
// stdin, the last ones at the end.
#pragma once

#include <string>
#include <vector>

namespace skinfem::app {

class ReportFigures {
 public:
  explicit ReportFigures(std::string out_dir);
  // Draws `only` (figure names) now, beside the stages still to come.
  void draw_now(const std::vector<std::string>& only);
  // Starts an interpreter for every figure but `except`; it waits for go() to draw them.
  void draw_on_go(const std::vector<std::string>& except);
  void go();
  // Draws `last` (may be empty) and waits for every interpreter. Returns the first non-zero exit code, or 0;
  // *stopped_by: the signal (SIGINT, SIGTERM, SIGHUP) that stopped the last drawing, which is passed on to
  // the others, or 0.
  int finish(const std::vector<std::string>& last, int* stopped_by);

 private:
  std::string out_dir_, script_;
  std::vector<int> children_;
  int go_fd_ = -1;  // the waiting interpreter's stdin
};

}  // namespace skinfem::app
