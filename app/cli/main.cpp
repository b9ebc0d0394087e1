// SPDX-License-Identifier: GPL-3.0-or-later
#include <iostream>

#include "command.hpp"
#include "lpt_emulator.hpp"
#include "pipeline/translation_workers.hpp"
#include "platform/console.hpp"

int main(int argc, char** argv) {
    // Started again as a translation worker (Windows): that and nothing else.
    if (const auto worker = tactus::pipeline::run_translation_worker(argc, argv)) return *worker;
    using namespace tactus::cli;
    tactus::platform::binary_standard_streams();  // the same bytes out on every system
    register_emulated_lpt();  // lpt:emu?fw=...: the firmware's pins in s51
    CLI::App app{"Tactus: translate, lay out and emboss braille", "tactus-cli"};
    app.set_version_flag("--version", "tactus-cli 0.1.0");
    app.require_subcommand(1);
    app.footer(
        "Exit status: 0 success, 1 the job did not complete, 2 usage error, 3 bad input\n"
        "(file:line: reason on stderr), 4 device error, 5 ready-made braille with pages\n"
        "larger than the target page (--reflow lays it out again), 6 internal error (a bug\n"
        "in Tactus or liblouis, e.g. a translation worker that crashed; never the input).");
    add_translate_command(app);
    add_layout_command(app);
    add_tables_command(app);
    add_queue_command(app);
    add_serve_command(app);
    add_plan_command(app);
    add_profile_command(app);
    add_vibration_command(app);
    add_sim_command(app);
    add_ports_command(app);
    add_emboss_command(app);
    add_convert_command(app);
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        app.exit(e);
        return exit_usage;
    } catch (const CommandFailed& e) {
        std::cerr << "tactus-cli: " << e.what() << '\n';
        return e.code;
    }
    return exit_ok;
}
