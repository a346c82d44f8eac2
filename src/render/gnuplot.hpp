// Running gnuplot without a shell (posix_spawnp, found in PATH): the script, data included as
// datablocks, goes to its stdin, its stdout is discarded and its stderr kept for the message of
// a failure; a gnuplot that neither reads nor exits within a time limit is killed. The PNG it
// draws is written like every result file (cert/atomic_file.hpp): into an exclusive temporary
// file beside the target, checked to be a PNG, then renamed over it. Users: plot.cpp (curves)
// and packing_picture.cpp (3-D packings). Every failure is a RenderError (render_error.hpp).
#pragma once
#include <functional>
#include <string>

namespace superpack::gnuplot {

// A gnuplot single-quoted string: nothing is special inside but the quote, written twice. A
// line break would end the command: RenderError.
std::string quoted(const std::string& text);

// `path` as gnuplot's `set output` must be given it: gnuplot reads "~..." as the home
// directory and "|..." as a command, so a relative path becomes "./...", the same file.
std::string output_path(const std::string& path);

// A number in the C locale with `digits` significant digits.
std::string number(double value, int digits = 12);

// Runs gnuplot with `script` on its stdin; returns only when it exited 0 having read all of
// it, and throws RenderError naming the problem otherwise (not found, failed with its last
// message line, killed, stopped after the time limit).
void run(const std::string& script);

// Writes the PNG `path` atomically: `script_for(output)` is a script that draws into the file
// `output` (a fresh temporary beside `path`; the script sets the terminal and output itself,
// with output_path); throws RenderError when gnuplot fails or writes no PNG, and then
// leaves `path` as it was and no temporary.
void write_png(const std::string& path, const std::function<std::string(const std::string& output)>& script_for);

}  // namespace superpack::gnuplot
