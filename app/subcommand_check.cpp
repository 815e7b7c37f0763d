#include "app/subcommand_check.h"

#include "common/closest_name.h"
#include "common/printable.h"

#include <vector>

namespace grotto::app {

std::string subcommandError(CLI::App& app, int argc, const char* const* argv) {
    CLI::App* command = &app;
    std::string chain = app.get_name();
    for (int i = 1;; ++i) {
        // Option groups are nameless subcommands to CLI11: not words a user types.
        const std::vector<CLI::App*> subcommands =
            command->get_subcommands([](CLI::App* sub) { return !sub->get_name().empty(); });
        if (subcommands.empty()) return "";
        std::vector<std::string> names;
        std::string list;
        for (const CLI::App* sub : subcommands) {
            names.push_back(sub->get_name());
            list += (list.empty() ? "" : ", ") + sub->get_name();
        }
        const std::string where = command == &app ? "" : " of '" + chain + "'";
        if (i >= argc) {
            if (command->get_require_subcommand_min() == 0) return "";
            return "'" + chain + "' requires a subcommand (subcommands: " + list + ")";
        }
        const std::string word = argv[i];
        if (!word.empty() && word[0] == '-') return "";
        CLI::App* next = nullptr;
        for (CLI::App* sub : subcommands)
            if (sub->check_name(word)) next = sub;
        if (!next) {
            const std::string meant = closestName(word, names);
            return "unknown subcommand '" + printable(word) + "'" + where + " (" +
                   (meant.empty() ? "" : "did you mean '" + meant + "'? ") + "subcommands: " + list + ")";
        }
        command = next;
        chain += " " + next->get_name();
    }
}

}  // namespace grotto::app
