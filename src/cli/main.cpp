// superpack: certified enclosures for dense superball and superdisk packings.
#include <algorithm>
#include <cstdlib>

#include "common.hpp"
#include "superpack/certificate.hpp"
#include "superpack/version.hpp"

int main(int argc, char** argv) {
    using namespace superpack::cli;
    CLI::App app{"superpack: certified enclosures for dense superball and superdisk packings.\n"
                 "Every number printed is a rigorous interval [lo, hi]."};
    app.require_subcommand(1);
    app.set_version_flag("--version", superpack::version());
    auto registry = subcommand_registry();
    std::sort(registry.begin(), registry.end());
    for (const auto& entry : registry) entry.second(app);
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& help) {
        return app.exit(help);
    } catch (const CLI::CallForAllHelp& help) {
        return app.exit(help);
    } catch (const CLI::CallForVersion& version) {
        return app.exit(version);
    } catch (const CLI::ParseError& error) {
        std::cerr << "superpack: error: " << error.what() << "\n";
        return exit_usage;
    } catch (const superpack::InputError& error) {
        std::cerr << "superpack: error: " << error.what() << "\n";
        return exit_usage;
    } catch (const superpack::CertificateRejected& error) {
        std::cerr << "superpack: error: no certificate written: " << error.what() << "\n";
        return exit_invalid;
    } catch (const Failure& failure) {
        std::cerr << "superpack: " << failure.what() << "\n";
        return failure.code;
    } catch (const std::exception& error) {
        std::cerr << "superpack: internal error: " << error.what() << "\n";
        return EXIT_FAILURE;
    }
    return exit_ok;
}
