// `ricochet help [COMMAND]`, and the command-name check main() makes before parsing: a word that names
// no command is "unknown command 'replya'; did you mean 'replay'?" (exit 2), not CLI11's "A subcommand
// is required".
#include <fmt/format.h>

#include "commands.hpp"
#include "suggest.hpp"

namespace ricochet::cli {

std::vector<std::string> command_names(const CLI::App& app) {
    std::vector<std::string> names;
    for (const CLI::App* s : app.get_subcommands([](const CLI::App* c) { return !c->get_group().empty(); }))
        names.push_back(s->get_name());
    return names;
}

std::string program_help(const CLI::App& app) {
    // The formatter directly: app.help() would show the help of the command being run (`help` itself).
    return app.get_formatter()->make_help(&app, app.get_name(), CLI::AppFormatMode::Normal);
}

bool is_command(const CLI::App& app, const std::string& word) {
    // Hidden commands too: `__complete` is called by the completion scripts.
    const auto all = app.get_subcommands([](const CLI::App*) { return true; });
    return std::any_of(all.begin(), all.end(), [&](const CLI::App* s) { return s->get_name() == word; });
}

void print_unknown_command(const CLI::App& app, const std::string& word) {
    const auto names = command_names(app);
    if (const auto near = nearest_name(word, names))
        fmt::print(stderr, "ricochet: error: unknown command '{}'; did you mean '{}'?\n", word, *near);
    else
        fmt::print(stderr, "ricochet: error: unknown command '{}' (commands: {})\n", word, fmt::join(names, ", "));
    fmt::print(stderr, "Run 'ricochet help' for the list of commands.\n");
}

void register_help(CLI::App& app) {
    auto command = std::make_shared<std::string>();
    CLI::App* sub = app.add_subcommand("help", "print this help, or a command's (ricochet help COMMAND)");
    sub->add_option("COMMAND", *command, "the command to explain");
    sub->callback([&app, command] {
        if (command->empty()) {
            write_stdout(program_help(app));
            return;
        }
        if (!is_command(app, *command)) {
            print_unknown_command(app, *command);
            throw Exit{2};
        }
        write_stdout(app.get_subcommand(*command)->help(app.get_name()));
    });
}

}  // namespace ricochet::cli
