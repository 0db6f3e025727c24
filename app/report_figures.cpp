#include "app/report_figures.hpp"

#include <signal.h>

#include "app/common.hpp"

namespace skinfem::app {

namespace {
std::string comma_list(const std::vector<std::string>& names) {
  std::string s;
  for (const std::string& n : names) s += (s.empty() ? "" : ",") + n;
  return s;
}
}  // namespace

ReportFigures::ReportFigures(std::string out_dir) : out_dir_(std::move(out_dir)), script_(figures_script()) {}

void ReportFigures::draw_now(const std::vector<std::string>& only) {
  progress("figures: " + script_ + ", beside the stages to come");
  children_.push_back(
      start_background_child({"/usr/bin/python3", script_, out_dir_, "--only", comma_list(only)}));
}

void ReportFigures::draw_on_go(const std::vector<std::string>& except) {
  children_.push_back(start_background_child(
      {"/usr/bin/python3", script_, out_dir_, "--except", comma_list(except), "--wait-for-go"}, &go_fd_));
}

void ReportFigures::go() { tell_background_child(go_fd_, "go"); }

int ReportFigures::finish(const std::vector<std::string>& last, int* stopped_by) {
  progress(last.empty() ? "figures: the end of those drawn beside"
                        : "figures: the last ones, and the end of the others");
  *stopped_by = 0;
  int rc = 0;
  if (!last.empty())
    rc = run_child({"/usr/bin/python3", script_, out_dir_, "--only", comma_list(last)}, stopped_by);
  if (*stopped_by != 0)
    for (const int child : children_) kill(child, *stopped_by);
  for (const int child : children_)
    if (const int c = wait_background_child(child); rc == 0) rc = c;
  children_.clear();
  return rc;
}

}  // namespace skinfem::app
