#pragma once
// Text for the self-contained HTML pages (the batch summary, a run's report.html): escaping,
// files carried inside the page as base64, and figures as every report prints them.

#include <filesystem>
#include <string>

namespace lathesim::batch {

/// `text` safe inside HTML text and attribute values.
std::string escaped(const std::string& text);

/// `bytes` in base64 (RFC 4648, with padding), as data: URLs take it.
std::string base64(const std::string& bytes);

/// The file's bytes; empty if it cannot be read.
std::string fileBytes(const std::filesystem::path& file);

/// `value` with `decimals` digits after the point, rounded as printf's %.*f rounds.
std::string fixed(double value, int decimals);

}  // namespace lathesim::batch
