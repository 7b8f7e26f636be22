#pragma once
// The command line's words checked before CLI11 parses them, for the mistakes CLI11 turns into something else.
namespace CLI {
class App;
}

namespace vssw::cli {

// InputError naming the word when one of the command's words is
// - not UTF-8 (a path with the byte 0xff): the JSON outputs and pages hold every path and name as UTF-8;
// - a single-dash word of several letters ("-height 4"): CLI11 reads it as the short flags -h -e -i ..., so it printed
//   the help and exited 0; "unknown option -height; did you mean --height?";
// - an option given without its value before another option ("--height --thickness=0.4"): CLI11 takes the next word as
//   the value whatever it is ("Could not convert: --height = --thickness=0.4");
// - an option with an empty value after '=' ("--height="): CLI11 then takes the next word as the value too.
// `app` is the program with its commands added; argv as main() gets it.
void check_argument_words(const CLI::App& app, int argc, const char* const* argv);

}  // namespace vssw::cli
