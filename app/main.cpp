// grotto: the command line. Exit codes: 0 success, 2 bad input or usage,
// 1 internal failure, 3 a measurement worse than its baseline (stability
// --baseline); errors are one line, never a raw exception trace.
#include "app/commands.h"
#include "common/closest_name.h"
#include "grotto/error.h"
#include "common/printable.h"

#include <algorithm>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

int main(int argc, char** argv) {
    CLI::App app{"grotto: voxel deferred renderer with temporal GTAO", "grotto"};
    app.require_subcommand(1);
    app.set_version_flag("--version", "grotto " GROTTO_VERSION);
    // Usage errors get one line too, like every other error.
    app.failure_message([](const CLI::App*, const CLI::Error& e) {
        return "grotto: error: " + grotto::printable(e.what()) + " (see --help)\n";
    });
    grotto::app::addRenderCommand(app);
    grotto::app::addInfoCommand(app);
    grotto::app::addMkworldCommand(app);
    grotto::app::addExportMeshCommand(app);
    grotto::app::addBenchCommand(app);
    grotto::app::addFlythroughCommand(app);
    grotto::app::addReferenceCommand(app);
    grotto::app::addStabilityCommand(app);
    grotto::app::addTradeoffCommand(app);
    grotto::app::addTuneCommand(app);
    grotto::app::addCompareCommand(app);
    grotto::app::addViewCommand(app);
    grotto::app::addBakeCommand(app);
    grotto::app::addPathCommand(app);
    grotto::app::addConvertCommand(app);
    grotto::app::refuseEmptyValues(app);
    // Bare `grotto` is a usage error, but one worth the whole usage: on stdout,
    // with the usual one line on stderr.
    if (argc < 2) {
        std::fputs(app.help().c_str(), stdout);
        std::fprintf(stderr, "grotto: error: a subcommand is required (usage above)\n");
        return 2;
    }
    // CLI11 takes an unknown first word for a stray argument and asks for a
    // subcommand: name the word instead, and the subcommand it was likely meant to be.
    const std::vector<CLI::App*> subcommands = app.get_subcommands({});
    const std::string word = argv[1];
    if (!word.empty() && word[0] != '-' &&
        std::none_of(subcommands.begin(), subcommands.end(), [&](CLI::App* sub) { return sub->check_name(word); })) {
        std::vector<std::string> names;
        for (const CLI::App* sub : subcommands) names.push_back(sub->get_name());
        const std::string meant = grotto::closestName(word, names);
        const std::string hint = meant.empty() ? "see --help for the subcommands" : "did you mean '" + meant + "'? see --help";
        std::fprintf(stderr, "grotto: error: unknown subcommand '%s' (%s)\n", grotto::printable(word).c_str(), hint.c_str());
        return 2;
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return code == 0 ? 0 : 2;
    } catch (const grotto::Error& e) {
        const bool regression = e.kind() == grotto::Error::Kind::Regression;
        std::fprintf(stderr, "grotto: %s: %s\n", regression ? "regression" : "error", grotto::printable(e.what()).c_str());
        return e.exitCode();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "grotto: internal error: %s\n", grotto::printable(e.what()).c_str());
        return 1;
    }
    return 0;
}
