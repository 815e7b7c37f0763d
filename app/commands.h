#pragma once
// One function per subcommand, each in its own file; main() wires them up.
#include <CLI/CLI.hpp>

namespace grotto::app {

void addRenderCommand(CLI::App& app);
void addInfoCommand(CLI::App& app);
void addMkworldCommand(CLI::App& app);
void addExportMeshCommand(CLI::App& app);
void addBenchCommand(CLI::App& app);
void addFlythroughCommand(CLI::App& app);
void addReferenceCommand(CLI::App& app);
void addStabilityCommand(CLI::App& app);
void addTradeoffCommand(CLI::App& app);
void addTuneCommand(CLI::App& app);
void addCompareCommand(CLI::App& app);
void addViewCommand(CLI::App& app);
void addBakeCommand(CLI::App& app);
void addPathCommand(CLI::App& app);
void addConvertCommand(CLI::App& app);

// Every option of `app` and of its subcommands that takes a value refuses an
// empty one, naming the flag (exit 2): CLI11 would take '' as the type's empty
// value, so `--chunk ''` meant no chunk and `--radius ''` the default.
void refuseEmptyValues(CLI::App& app);

}  // namespace grotto::app
