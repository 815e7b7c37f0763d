// grotto: the command line. Exit codes: 0 success, 2 bad input or usage,
// 1 internal failure, 3 a measurement worse than its baseline (stability
// --baseline); errors are one line, never a raw exception trace.
#include "app/commands.h"
#include "app/subcommand_check.h"
#include "grotto/error.h"
#include "common/printable.h"

#include <cstdio>
#include <exception>
#include <string>

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
    // An unknown or missing subcommand at any level, named with those accepted
    // there (app/subcommand_check.h). Bare `grotto` is worth the whole usage
    // besides: on stdout, with the same one line on stderr.
    if (const std::string usage = grotto::app::subcommandError(app, argc, argv); !usage.empty()) {
        if (argc < 2) std::fputs(app.help().c_str(), stdout);
        std::fprintf(stderr, "grotto: error: %s\n", usage.c_str());
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
