#pragma once

#include <functional>
#include <ostream>
#include <string>
#include <string_view>

namespace sweetspot::io {

// Writes `content` to `path` through a temporary file in the same directory
// and rename(2): readers see the old file or the whole new one, never part of
// it, and a failed run leaves an existing file untouched. Throws
// std::runtime_error naming the path when the file cannot be written.
void write_file_atomically(const std::string& path, std::string_view content);

// The same for output produced as a stream (a sweep, a batch): `write` fills
// a temporary file beside `path`, which replaces `path` only when complete.
// If `write` throws, the temporary is removed and the exception goes on.
void write_stream_atomically(const std::string& path, const std::function<void(std::ostream&)>& write);

// A temporary path beside `path` for a writer that is not ours (gnuplot);
// commit_file() renames it over `path`, discard_file() removes it.
std::string temporary_path_for(const std::string& path);
void commit_file(const std::string& temporary, const std::string& path);
void discard_file(const std::string& temporary);

}  // namespace sweetspot::io
