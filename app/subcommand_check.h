#pragma once
// The subcommand words of a command line, checked before CLI11 parses it: CLI11
// takes an unknown word for a stray argument and says "A subcommand is
// required", even under `grotto path check`. Here the word is named, with the
// subcommands accepted where it stands.
#include <CLI/CLI.hpp>

#include <string>

namespace grotto::app {

// The one-line error for argv's first word that should name a subcommand and
// names none ("unknown subcommand 'check' of 'grotto path' (subcommands:
// import)"), or for a command that requires a subcommand and got none; empty when
// the subcommands are all known or an option comes first (CLI11 parses the rest).
std::string subcommandError(CLI::App& app, int argc, const char* const* argv);

}  // namespace grotto::app
