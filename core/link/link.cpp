// SPDX-License-Identifier: GPL-3.0-or-later
#include "link/link.hpp"

#include "link/link_impl.hpp"
#include "controller/open_device.hpp"
#include "transport/device.hpp"
#include "common/try.hpp"

namespace tactus::link {

Link::Link(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Link::Link(Link&&) noexcept = default;
Link& Link::operator=(Link&&) noexcept = default;
Link::~Link() = default;

Result<Link> Link::open(std::string_view device, LinkOptions options) {
    TACTUS_TRY(s, controller::open_device(device, options.sim_firmware));
    auto link = over(std::move(s), options);
    link.impl_->device = std::string(device);
    return link;
}

Link Link::over(std::unique_ptr<transport::ByteStream> stream, LinkOptions options) {
    auto impl = std::make_unique<Impl>();
    impl->device = stream->describe();
    impl->s = std::move(stream);
    impl->opt = options;
    return Link(std::move(impl));
}

Result<HelloReply> Link::hello() { return impl_->hello(); }

Result<void> Link::configure(const machine::ControllerConfig& config) {
    impl_->config = config;
    TACTUS_TRY(payload, impl_->config_payload());
    return impl_->transact(FrameType::configure, std::move(payload));
}

Result<void> Link::use_firmware_tables(const machine::FirmwareTables& tables, const machine::StrikeTiming& timing) {
    return impl_->use_firmware_tables(tables, timing);
}

std::uint8_t Link::protocol() const { return impl_->session ? impl_->info.protocol : 0; }

Result<Status> Link::status() { return impl_->status(); }
Result<void> Link::pause() { return impl_->transact(FrameType::pause, {}); }
Result<void> Link::resume() { return impl_->transact(FrameType::resume, {}); }
Result<void> Link::abort() { return impl_->transact(FrameType::abort, {}); }

Result<void> Link::reconnect() {
    if (auto r = impl_->reconnect_device(); !r) return r;
    TACTUS_TRY_VOID(impl_->hello());
    return {};
}

void Link::request_pause() { impl_->pause_req = true; }
void Link::request_resume() { impl_->resume_req = true; }
const LinkStats& Link::stats() const { return impl_->stats; }
std::string Link::device() const { return impl_->device; }
transport::ByteStream& Link::stream() { return *impl_->s; }

Result<JobOutcome> Link::send_job(const plan::JobPlan& plan, std::size_t start_sheet,
                                  const ProgressFn& progress, const CancelToken& cancel,
                                  std::uint16_t job_id) {
    return impl_->send_job(plan, start_sheet, progress, cancel, job_id);
}

}  // namespace tactus::link
