#pragma once
// report.html's "Tools and stock": report.json's "stock" and "tools" as two tables.

#include <nlohmann/json.hpp>
#include <string>

namespace lathesim::app {

/// The section, or "" when the report has neither (a report of an older lathesim).
std::string toolTableHtml(const nlohmann::ordered_json& report);

}  // namespace lathesim::app
