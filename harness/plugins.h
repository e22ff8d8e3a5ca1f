// External algorithms, in any language (docs/CONTRACT.md, "External algorithms"). A manifest, one JSON
// file, names the algorithm, its kind, claimed bounds and accepted input, and the command that runs it:
//
//   {"name": "my-fan", "kind": "triangulation", "time_bound": "n", "pieces_bound": "== n-2",
//    "source": "...", "accepts": {"convex_only": true}, "command": ["python3", "fan.py"]}
//
// The command runs in the manifest's folder, is started on the first polygon it is given and kept for
// the next ones (once per sweep, not per key), and speaks JSON lines: it reads one polygon per line,
// {"points": [[x, y], ...], "holes": []} (the polygon counter-clockwise, as the checked constructor made
// it), and writes one result per line, {"pieces": [[i, j, k, ...], ...], "steiner": [[x, y], ...],
// "seconds": t} (indices into the points sent, Steiner point k as index n + k, coordinates numbers or
// "p/q" strings, t its own timing of the algorithm alone), or {"error": "..."} for a refusal. It is then
// registered like any algorithm: listed, run, validated and benchmarked. Its crash, exit or garbled line
// fails the call it happened in (a std::runtime_error naming it), and the next call starts it again;
// it is killed when polydecomp ends. A hang is stopped by `run --max-seconds` or the sweep's timeout.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace pd {

// A manifest that is not one, or a folder that cannot be read; what() names the file and the problem.
class PluginError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The folders searched for manifests: the project's peers/, then the `--plugins` folders given, then
// those in POLYDECOMP_PLUGINS (colon-separated).
std::vector<std::string> plugin_folders(const std::vector<std::string>& given);

// Registers the algorithm of every *.json manifest in `folders` (sorted by file name). A missing
// folder other than the project's peers/ is an error.
void register_plugins(const std::vector<std::string>& folders);

// From now on the commands are forked from one long-lived thread (plugins.cpp, Launcher), not from the
// calling thread, whose end would take them with it. For a host whose calls come from threads that end
// (the Python module); call it once, before other threads run.
void use_plugin_launcher();

}  // namespace pd
