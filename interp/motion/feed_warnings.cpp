#include "interp/motion/feed_warnings.hpp"

#include <fmt/format.h>

namespace lathesim::interp {

std::optional<std::string> implausibleFeed(const std::string& written, double feedMm, FeedMode mode, bool inch) {
  const bool perRevolution = mode == FeedMode::PerRevolution;
  const char* per = perRevolution ? "revolution" : "minute";
  // "0.2 mm", or "0.012 inch (0.3048 mm)": the program's own unit first.
  const double asWritten = inch ? feedMm / 25.4 : feedMm;
  const std::string amount = inch ? fmt::format("{:g} inch ({:g} mm)", asWritten, feedMm) : fmt::format("{:g} mm", feedMm);
  const char* code = perRevolution ? "G99" : "G98";
  const char* unit = inch ? "inch" : "mm";
  if (perRevolution && feedMm > kMaxPlausibleFeedMmPerRev)
    return fmt::format("{} under {} is {} per {}; did you mean G98 ({} per minute)?", written, code, amount, per, unit);
  if (perRevolution && feedMm < kMinPlausibleFeedMmPerRev) {
    return fmt::format("{} under {} is {} per {}, finer than a cutting edge takes (below {:g} mm); check the "
                       "decimal point and the unit",
                       written, code, amount, per, kMinPlausibleFeedMmPerRev);
  }
  if (!perRevolution && feedMm < kMinPlausibleFeedMmPerMin)
    return fmt::format("{} under {} is {} per {}; did you mean G99 ({} per revolution)?", written, code, amount, per,
                       unit);
  return std::nullopt;
}

}  // namespace lathesim::interp
