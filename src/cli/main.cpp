// superpack: certified enclosures for dense superball and superdisk packings.
#include "command_line.hpp"

int main(int argc, char** argv) {
    const superpack::cli::CommandOutcome outcome = superpack::cli::run_command_line(argc, argv);
    if (outcome.code == 0) return 0;
    return superpack::cli::report_failure(outcome);
}
