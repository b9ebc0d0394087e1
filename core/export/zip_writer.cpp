// SPDX-License-Identifier: GPL-3.0-or-later
#include "export/zip_writer.hpp"

#include <zip.h>

#include <memory>

namespace tactus::exporter {
namespace {

// 1980-01-01, the first time a ZIP header can hold: no clock in the output.
constexpr time_t kFixedTime = 315532800;

struct SourceFree {
    void operator()(zip_source_t* s) const { zip_source_free(s); }
};

Error zip_failure(const std::string& what, zip_error_t* error) {
    return Error{"cannot build the package: " + what + ": " + zip_error_strerror(error), {}, ErrorKind::internal};
}

}  // namespace

Result<std::string> zip_package(const std::vector<ZipPart>& parts) {
    zip_error_t error;
    zip_error_init(&error);
    std::unique_ptr<zip_source_t, SourceFree> buffer(zip_source_buffer_create(nullptr, 0, 0, &error));
    if (!buffer) {
        auto e = zip_failure("buffer", &error);
        zip_error_fini(&error);
        return std::unexpected(e);
    }
    zip_t* z = zip_open_from_source(buffer.get(), ZIP_TRUNCATE, &error);
    if (!z) {
        auto e = zip_failure("open", &error);
        zip_error_fini(&error);
        return std::unexpected(e);
    }
    zip_error_fini(&error);
    // The archive holds the buffer now; one more reference reads it back
    // after zip_close.
    zip_source_keep(buffer.get());
    for (const auto& part : parts) {
        // The part's bytes live in `parts` until zip_close has written them.
        zip_source_t* data = zip_source_buffer(z, part.bytes.data(), part.bytes.size(), 0);
        const zip_int64_t index = data ? zip_file_add(z, part.name.c_str(), data, ZIP_FL_ENC_UTF_8) : -1;
        if (index < 0) {
            if (data) zip_source_free(data);
            auto e = zip_failure(part.name, zip_get_error(z));
            zip_discard(z);
            return std::unexpected(e);
        }
        const auto i = static_cast<zip_uint64_t>(index);
        if (zip_set_file_compression(z, i, part.stored ? ZIP_CM_STORE : ZIP_CM_DEFLATE, 0) < 0 ||
            zip_file_set_mtime(z, i, kFixedTime, 0) < 0) {
            auto e = zip_failure(part.name, zip_get_error(z));
            zip_discard(z);
            return std::unexpected(e);
        }
    }
    if (zip_close(z) < 0) {
        auto e = zip_failure("close", zip_get_error(z));
        zip_discard(z);
        return std::unexpected(e);
    }
    zip_stat_t st;
    zip_stat_init(&st);
    if (zip_source_stat(buffer.get(), &st) < 0 || zip_source_open(buffer.get()) < 0)
        return std::unexpected(zip_failure("read back", zip_source_error(buffer.get())));
    std::string out(static_cast<std::size_t>(st.size), '\0');
    const auto got = zip_source_read(buffer.get(), out.data(), st.size);
    zip_source_close(buffer.get());
    if (got < 0 || static_cast<zip_uint64_t>(got) != st.size)
        return std::unexpected(zip_failure("read back", zip_source_error(buffer.get())));
    return out;
}

}  // namespace tactus::exporter
