#include "app/watch/watch_page.hpp"

#include <nlohmann/json.hpp>

namespace lathesim::app {
namespace {

// The page keeps the generation of the outputs it shows; a newer one reloads it.
constexpr const char* kScript = R"js(
<script>
(function () {
  const shown = SHOWN_GOOD;
  const scrollKey = 'lathesim-watch-scroll';
  const saved = sessionStorage.getItem(scrollKey);
  if (saved !== null) { sessionStorage.removeItem(scrollKey); window.scrollTo(0, Number(saved)); }
  const banner = document.createElement('div');
  banner.id = 'watch-banner';
  banner.style.cssText = 'position:sticky;top:0;z-index:10;padding:8px 24px;font:14px/1.4 system-ui,sans-serif;display:none';
  const title = document.createElement('div');
  const details = document.createElement('pre');
  details.style.cssText = 'margin:6px 0 0;white-space:pre-wrap;font:13px/1.35 ui-monospace,monospace';
  banner.append(title, details);
  document.body.prepend(banner);
  function show(color, text, more) {
    banner.style.display = 'block';
    banner.style.background = color;
    banner.style.color = color === '#c5221f' ? '#fff' : '#1f2329';
    title.textContent = text;
    details.textContent = more || '';
    details.style.display = more ? 'block' : 'none';
  }
  async function poll() {
    let state;
    try {
      state = await (await fetch('watch/state', { cache: 'no-store' })).json();
    } catch (e) {
      show('#dde1e6', 'lathesim watch has stopped: this page no longer follows the program.');
      return;
    }
    if (state.good_generation !== shown) {
      sessionStorage.setItem(scrollKey, String(window.scrollY));
      location.reload();
      return;
    }
    if (state.running) show('#dde1e6', 'Running the program again…');
    else if (state.error) show('#c5221f', 'The last save did not run (exit status ' + state.status + ')' +
                                 (shown ? ': the part below is from the last run that did.' : '.'), state.error);
    else banner.style.display = 'none';
    setTimeout(poll, 700);
  }
  setTimeout(poll, 700);
})();
</script>
)js";

std::string script(const WatchState& served) {
  std::string text = kScript;
  const std::string marker = "SHOWN_GOOD";
  text.replace(text.find(marker), marker.size(), std::to_string(served.goodGeneration));
  return text;
}

}  // namespace

std::string stateJson(const WatchState& state) {
  return nlohmann::ordered_json{{"generation", state.generation},
                                {"good_generation", state.goodGeneration},
                                {"running", state.running},
                                {"status", state.status},
                                {"error", state.error}}
      .dump();
}

std::string withWatchScript(std::string html, const WatchState& served) {
  const auto end = html.rfind("</body>");
  html.insert(end == std::string::npos ? html.size() : end, script(served));
  return html;
}

std::string waitingPage(const WatchState& state) {
  return "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>lathesim watch</title></head>\n"
         "<body style=\"font:15px/1.45 system-ui,sans-serif;margin:0\">\n"
         "<main style=\"padding:16px 24px\"><p>No part yet: no run of the program has written its outputs.</p></main>\n" +
         script(state) + "</body></html>\n";
}

}  // namespace lathesim::app
