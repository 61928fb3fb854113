#pragma once
// Writes that never leave a half-written file: the content goes to a
// temporary file beside the target, which is renamed over it only once the
// writer has succeeded. On any failure the temporary is removed and the old
// target (if any) is untouched.

#include <functional>
#include <ostream>
#include <string>

namespace mtcut::engine {

// Calls write(temp_path) to produce the file, then renames it to path.
// write reports failure by throwing or by returning false. Throws InputError.
void write_atomically(const std::string& path, const std::function<bool(const std::string& temp_path)>& write);

// Convenience for text and binary streams: write(out) fills an ofstream.
void write_stream_atomically(const std::string& path, const std::function<void(std::ostream& out)>& write);

}  // namespace mtcut::engine
