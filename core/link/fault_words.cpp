// SPDX-License-Identifier: GPL-3.0-or-later
#include "link/fault_words.hpp"

namespace tactus::link {

std::string explain_faults(std::uint8_t f) {
    namespace fault = encode::fault;
    std::string out;
    const auto add = [&out](const char* s) {
        if (!out.empty()) out += ' ';
        out += s;
    };
    if (f & fault::paper_out) add("Paper out: put paper in the feeder; the job goes on by itself.");
    if (f & fault::limit_switch)
        add("The carriage reached a limit switch: check that nothing blocks it and that the paper is straight, then resume.");
    if (f & fault::hammer) add("A hammer did not come back: switch the embosser off, free the hammer, then resume from the sheet shown.");
    if (f & fault::power_on_reset) add("The embosser restarted after losing power: the job resumes from the first unfinished sheet.");
    if (f & fault::warm_reset) add("The controller restarted but kept its place: the job continues.");
    if (f & fault::host_timeout) add("The embosser stopped hearing from this computer and paused: check the cable.");
    if (f & fault::underrun) add("The embosser ran out of data in a move (should not happen): report it with the link log.");
    if (f & fault::stream_error) add("The embosser rejected the job data: report it with the link log.");
    return out;
}

std::string explain_status(const encode::Status& s) {
    namespace st = encode::flag;
    std::string out = encode::state_name(s.ack.state);
    out += (s.flags & st::configured) ? ", configured" : ", not configured";
    out += (s.flags & st::homed) ? ", carriage homed" : ", carriage not homed";
    out += (s.flags & st::paper_present) ? ", paper loaded" : ", no paper";
    if (s.flags & st::job_active) out += ", printing sheet " + std::to_string(s.sheet);
    if (s.ack.faults) out += ". " + explain_faults(s.ack.faults);
    return out;
}

}  // namespace tactus::link
