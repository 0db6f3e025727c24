// The scene module's JSON input, shared by scene files (load.cpp) and sweep specs (sweep.cpp): one set of
// rules for reading a file and parsing its text. Internal to scene/, the only JSON reader in skinfem.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace skinfem {

// The whole file at `path`; `what` names it in the error ("scene file", "sweep spec"). Throws SceneError,
// one line: "<path>: cannot read <what>: <reason>".
std::string read_text_file(const std::string& path, const std::string& what);

// Parses JSON text, refusing duplicate keys (which nlohmann would silently resolve to the last one). Throws
// SceneError, one line naming `file` and, for a duplicate, the key's path.
nlohmann::json parse_json_text(const std::string& text, const std::string& file);

}  // namespace skinfem
