// SPDX-License-Identifier: GPL-3.0-or-later
#include "spool/print_job.hpp"

#include <algorithm>
#include <optional>
#include <span>
#include <utility>

#include <nlohmann/json.hpp>

#include "encode/frame.hpp"
#include "encode/messages.hpp"
#include "encode/stream.hpp"
#include "plan/planner.hpp"
#include "profile/controller_config.hpp"
#include "profile/firmware_tables.hpp"
#include "profile/profile_json.hpp"
#include "spool/printing.hpp"
#include "common/try.hpp"

namespace tactus::spool {
namespace {

// The one place a plan is paired with a controller configuration: both come
// from `profile`.
PrintJob assemble(plan::JobPlan plan, profile::PrinterProfile profile, int protocol, std::string_view device) {
    PrintJob job;
    job.config = profile::controller_config(profile);
    job.plan = std::move(plan);
    job.profile = std::move(profile);
    job.protocol = protocol;
    job.device = std::string(device);
    return job;
}

// The first place two profiles differ in anything the planner or the
// controller reads (the name is only a label), as a JSON path; empty when
// they do not.
std::string first_difference(const profile::PrinterProfile& a, const profile::PrinterProfile& b) {
    for (const auto& op : nlohmann::json::diff(profile::to_json(a), profile::to_json(b))) {
        const auto path = op.value("path", std::string{});
        if (path != "/name") return path.empty() ? "/" : path;
    }
    return {};
}

}  // namespace

Result<PrintJob> make_print_job(const layout::PagedDocument& document, const profile::PrinterProfile& profile,
                                std::string_view device, std::size_t copies) {
    TACTUS_TRY(plan, plan_copies(document, profile, copies));
    return assemble(std::move(plan), profile, encode::kProtocolVersion, device);
}

Result<PrintJob> make_firmware_print_job(const layout::PagedDocument& document, const profile::PrinterProfile& profile,
                                         const machine::FirmwareTables& tables, std::string_view device,
                                         std::size_t copies) {
    TACTUS_TRY(plan, plan_copies(document, profile, copies, &tables));
    auto job = assemble(std::move(plan), profile, encode::kProtocolV3, device);
    job.firmware = tables;
    job.timing = profile::strike_timing(profile);
    return job;
}

Result<PrintJob> make_print_job(plan::PlanFile file, std::string_view device,
                                const profile::PrinterProfile* printer_profile) {
    if (file.protocol != encode::kProtocolVersion && file.protocol != encode::kProtocolV3)
        return fail(ErrorKind::input, "the plan was made for link protocol version " + std::to_string(file.protocol) +
                        "; this Tactus speaks versions " + std::to_string(encode::kProtocolVersion) + " and " +
                        std::to_string(encode::kProtocolV3) + ": plan the document again (`tactus-cli plan --json`)",
                    "plan.protocol");
    if (file.protocol == encode::kProtocolV3 && !file.firmware)
        return fail(ErrorKind::input, "a protocol-3 plan needs the ramp tables it was made with", "plan.firmware_tables");
    if (printer_profile) {
        const auto diff = first_difference(file.profile, *printer_profile);
        if (!diff.empty())
            return fail(ErrorKind::input, "the plan was made with profile '" + file.profile.name + "', which differs from the "
                            "printer's profile '" + printer_profile->name + "' at " + diff +
                            ": plan the document again with the printer's profile, or emboss the plan "
                            "without --profile (the controller is then configured with the plan's own)",
                        "plan.profile");
    }
    auto job = assemble(std::move(file.plan), std::move(file.profile), file.protocol, device);
    if (file.firmware) {
        job.firmware = std::move(file.firmware);
        job.timing = profile::strike_timing(job.profile);
    }
    return job;
}

plan::PlanFile to_plan_file(const PrintJob& job) {
    return plan::PlanFile{job.plan, job.profile, job.protocol, job.firmware};
}

Result<link::JobOutcome> send_print_job(link::Link& link, const PrintJob& job, std::size_t start_sheet,
                                        const link::ProgressFn& progress, const link::CancelToken& cancel,
                                        std::uint16_t job_id) {
    if (job.firmware)
        TACTUS_TRY_VOID(link.use_firmware_tables(*job.firmware, job.timing));
    TACTUS_TRY_VOID(link.configure(job.config));
    return link.send_job(job.plan, start_sheet, progress, cancel, job_id);
}

namespace {

// Ops on their way into DATA frames: chunk_stream packs them greedily, so a
// frame it closes never changes when more ops follow; only the last, open one
// is kept for the next sheet's ops.
class FrameCounter {
public:
    explicit FrameCounter(StreamSize& out) : out_(out) {}
    // Ops [from, to) of `s`.
    void add(const encode::JobStream& s, std::size_t from, std::size_t to) {
        const std::size_t begin = from == 0 ? 0 : s.op_ends[from - 1];
        const std::size_t end = to == 0 ? 0 : s.op_ends[to - 1];
        const std::size_t base = pending_.bytes.size();
        pending_.bytes.insert(pending_.bytes.end(), s.bytes.begin() + static_cast<std::ptrdiff_t>(begin),
                              s.bytes.begin() + static_cast<std::ptrdiff_t>(end));
        for (std::size_t i = from; i < to; ++i) pending_.op_ends.push_back(base + s.op_ends[i] - begin);
        out_.stream_bytes += end - begin;
    }
    void close(bool last) {
        const auto chunks = encode::chunk_stream(pending_, encode::kMaxPayload);
        const std::size_t closed = last || chunks.empty() ? chunks.size() : chunks.size() - 1;
        for (std::size_t k = 0; k < closed; ++k)
            out_.line_bytes += chunks[k].second - chunks[k].first + encode::kFrameOverhead;
        out_.frames += closed;
        if (last || chunks.empty()) return;
        const std::size_t cut = chunks.back().first;
        pending_.bytes.erase(pending_.bytes.begin(), pending_.bytes.begin() + static_cast<std::ptrdiff_t>(cut));
        std::erase_if(pending_.op_ends, [cut](std::size_t e) { return e <= cut; });
        for (auto& e : pending_.op_ends) e -= cut;
    }

private:
    StreamSize& out_;
    encode::JobStream pending_;
};

// Index of the op that starts the `nth` (1-based) SHEET_BEGIN of `s`.
std::size_t nth_sheet_begin(const encode::JobStream& s, int nth) {
    std::size_t begin = 0;
    for (std::size_t i = 0; i < s.op_ends.size(); ++i) {
        const auto op = encode::decode_op(std::span(s.bytes).subspan(begin, s.op_ends[i] - begin));
        if (op && op->first.code == encode::OpCode::sheet_begin && --nth == 0) return i;
        begin = s.op_ends[i];
    }
    return s.op_ends.size();
}

}  // namespace

Result<StreamSize> measure_print_job(const layout::PagedDocument& document, const profile::PrinterProfile& profile,
                                     std::size_t start_sheet) {
    TACTUS_TRY(planner, plan::Planner::create(profile));
    StreamSize out;
    FrameCounter frames(out);
    // The encoder carries one thing from sheet to sheet: the carriage position,
    // where the last sheet with strikes left it. Each sheet is encoded after
    // that sheet, and only its own ops are counted.
    std::optional<plan::SheetPlan> before;
    std::size_t passes = 0;
    bool started = false;
    const std::size_t sheets = document.sheet_count();
    plan::SheetQueue queue(planner, document);  // a few sheets ahead on the machine's cores
    for (std::size_t s = 1; s <= sheets; ++s) {
        TACTUS_TRY(sheet, queue.next());
        passes += sheet.passes.size();
        if (passes > encode::kMaxJobPasses)
            return fail(ErrorKind::input, "more than 65,535 passes in one job (" + std::to_string(passes) + " in the first " +
                            std::to_string(s) + " of " + std::to_string(sheets) +
                            " sheets); the controller counts at most 65,535",
                        "plan");
        ++out.sheets;
        for (const auto& p : sheet.passes) out.strikes += p.strikes.size();
        if (s >= start_sheet) {
            plan::JobPlan window;
            if (started && before) window.sheets.push_back(*before);
            window.sheets.push_back(sheet);
            TACTUS_TRY(stream, encode::encode_job(window, 1, {}));
            const std::size_t from = started ? nth_sheet_begin(stream, before ? 2 : 1) : 0;
            frames.add(stream, from, stream.op_ends.size() - 1);  // all but JOB_END
            frames.close(false);
            started = true;
        }
        bool strikes = false;
        for (const auto& p : sheet.passes) strikes = strikes || !p.strikes.empty();
        if (strikes) before = std::move(sheet);
    }
    if (!started) {
        // Nothing from start_sheet on: JOB_BEGIN, HOME and JOB_END alone.
        plan::JobPlan empty;
        TACTUS_TRY(stream, encode::encode_job(empty, 1, {}));
        frames.add(stream, 0, stream.op_ends.size());
    } else {
        encode::JobStream end;
        encode::Op job_end;
        job_end.code = encode::OpCode::job_end;
        encode::append_op(end.bytes, job_end);
        end.op_ends.push_back(end.bytes.size());
        frames.add(end, 0, 1);
    }
    frames.close(true);
    return out;
}

}  // namespace tactus::spool
