// write_file_atomically: a file is either written completely or not at all. The
// content goes to a new file PATH.tmp.XXXXXX first (a name no other writer has) and is
// renamed over PATH only after every byte was written and flushed, so a failure
// (exception, full disk) never leaves a partial PATH, and two runs writing PATH at once
// each leave their own complete file (the last rename wins).
#pragma once

#include <functional>
#include <ostream>
#include <string>

namespace tquad {

// Calls `write` with a stream on the temporary file, then renames it to PATH. Throws InputError
// naming the file when it cannot be created or written (a wrong output path is a
// user error); an exception thrown by `write` is passed on. The temporary file is
// removed on every failure.
void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write);

// Throws InputError when PATH cannot be an output, before any work is done: it exists
// and is not a regular file (a directory, or a device such as /dev/null that the
// final rename would replace), or its folder is missing or not writable (a read-only
// file system, or no permission).
void check_output_location(const std::string& path);

}  // namespace tquad
