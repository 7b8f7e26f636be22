#include "cli/argument_words.hpp"

#include <algorithm>
#include <cstdlib>
#include <string>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "analytic/error.hpp"
#include "cli/option_values.hpp"
#include "io/text.hpp"

namespace vssw::cli {
namespace {

// "-0.2", "-inf", "-1e-3": a value, not an option.
bool is_number(const std::string& word) {
    char* end = nullptr;
    (void)std::strtod(word.c_str(), &end);
    return !word.empty() && end == word.c_str() + word.size();
}

// A word CLI11 would read as one or more options: "-x...", "--name", not "-" (standard output for --csv) or a number.
bool looks_like_option(const std::string& word) { return word.size() > 1 && word[0] == '-' && !is_number(word); }

const CLI::App* subcommand_named(const CLI::App& app, const std::string& name) {
    const auto found = app.get_subcommands([&](const CLI::App* sub) { return sub->get_name() == name; });
    return found.empty() ? nullptr : found.front();
}

bool takes_value(const CLI::Option& option) {
    return option.get_items_expected_max() > 0 &&
           std::min(option.get_type_size_min(), option.get_items_expected_min()) > 0;
}

// Words that are not UTF-8 are refused before anything runs: a path or a name goes into the JSON outputs, the
// journal's study and the pages, all UTF-8; such a byte failed only when the JSON was written, after the whole run.
// `cmd` is the command the words belong to, to name the option whose value the word is.
void require_utf8_word(const CLI::App& cmd, const char* const* argv, int i) {
    const std::string word = argv[i];
    const auto mistake = io::not_utf8(word);
    if (!mistake) return;
    const std::size_t equals = word.find('=');
    const CLI::Option* option = nullptr;
    if (word.rfind("--", 0) == 0 && equals != std::string::npos) option = cmd.get_option_no_throw(word.substr(0, equals));
    else if (i > 1) option = cmd.get_option_no_throw(argv[i - 1]);
    const std::string what = option != nullptr && takes_value(*option) ? "the value of " + option->get_name() + ", "
                                                                       : "the argument ";
    throw InputError(fmt::format("{}{}: vssw writes paths and names as UTF-8 (JSON, pages); rename it", what, *mistake));
}

}  // namespace

void check_argument_words(const CLI::App& app, int argc, const char* const* argv) {
    const CLI::App* cmd = &app;
    int i = 1;
    // The command (and `study merge`): the first words, when they name one; the help names them all.
    std::string command = "vssw";
    while (i < argc) {
        const CLI::App* sub = subcommand_named(*cmd, argv[i]);
        if (sub == nullptr) break;
        cmd = sub;
        command += " " + sub->get_name();
        ++i;
    }
    const std::string help = command + " --help";
    for (int k = i; k < argc; ++k) require_utf8_word(*cmd, argv, k);
    for (; i < argc; ++i) {
        const std::string word = argv[i];
        if (word == "--") break;  // what follows are positional arguments
        if (!looks_like_option(word)) continue;
        if (word[1] != '-') {
            if (word.size() == 2) continue;  // -h
            const std::string long_name = "-" + word;
            if (cmd->get_option_no_throw(long_name) != nullptr)
                throw InputError(fmt::format("unknown option {}; did you mean {}?", word, long_name));
            throw InputError(fmt::format("unknown option {} (options start with --; see '{}')", word, help));
        }
        const std::size_t equals = word.find('=');
        const CLI::Option* option = cmd->get_option_no_throw(word.substr(0, equals));
        if (option == nullptr || !takes_value(*option)) continue;  // unknown ones: CLI11 names them
        if (equals != std::string::npos) {
            if (equals + 1 == word.size()) throw InputError(empty_value_message(*option));
            continue;
        }
        if (i + 1 < argc && looks_like_option(argv[i + 1]))
            throw InputError(fmt::format("{} needs a value, got none (the next word, {}, is an option)",
                                         option->get_name(), argv[i + 1]));
    }
}

}  // namespace vssw::cli
