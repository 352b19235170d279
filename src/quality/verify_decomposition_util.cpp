// Small helpers of verify_decomposition(): point formatting, the capped
// problem log.
#include "kernel/number_format.hpp"
#include "quality/verify_decomposition_detail.hpp"

namespace madd::detail {

std::string point_text(Point p) {
  std::string text = "(";
  append_g17(text, p.x);
  text += ", ";
  append_g17(text, p.y);
  text += ')';
  return text;
}

void ProblemLog::add(std::string problem) {
  if (count_++ < cap_) out_.add(std::move(problem));
}

void ProblemLog::absorb(std::vector<std::string>&& kept, std::size_t count) {
  for (std::string& problem : kept) add(std::move(problem));
  if (count > kept.size()) count_ += count - kept.size();
}

void ProblemLog::finish() {
  if (count_ > cap_) out_.add("... and " + std::to_string(count_ - cap_) + " more problems");
}

}  // namespace madd::detail
