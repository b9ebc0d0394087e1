// SPDX-License-Identifier: GPL-3.0-or-later
#include "import/zip_archive.hpp"

#include <zip.h>

namespace tactus::import::detail {

void ZipArchive::Closer::operator()(zip* z) const { zip_discard(z); }

Result<ZipArchive> ZipArchive::open(std::string_view bytes) {
    zip_error_t error;
    zip_error_init(&error);
    zip_source_t* source = zip_source_buffer_create(bytes.data(), bytes.size(), 0, &error);
    if (!source) {
        std::string why = zip_error_strerror(&error);
        zip_error_fini(&error);
        return fail(ErrorKind::input, "cannot read ZIP: " + why);
    }
    // Without libzip's strict check (ZIP_CHECKCONS), which refuses a package
    // whose local headers differ from its central directory in any field (a
    // modification time, say) though unzip, Python's zipfile, pandoc and Word
    // read it: what matters, the data, is still checked part by part (its CRC,
    // its size) when a part is read.
    zip_t* z = zip_open_from_source(source, ZIP_RDONLY, &error);
    if (!z) {
        std::string why = zip_error_strerror(&error);
        zip_error_fini(&error);
        zip_source_free(source);
        return fail(ErrorKind::input, "not a valid ZIP package (DOCX is one): " + why);
    }
    zip_error_fini(&error);
    return ZipArchive(z);
}

bool ZipArchive::contains(const std::string& part) const {
    return zip_name_locate(zip_.get(), part.c_str(), 0) >= 0;
}

Result<std::string> ZipArchive::read(const std::string& part, std::size_t max_bytes) const {
    zip_stat_t st;
    zip_stat_init(&st);
    if (zip_stat(zip_.get(), part.c_str(), 0, &st) != 0)
        return fail(ErrorKind::input, "missing part " + part, part);
    if ((st.valid & ZIP_STAT_SIZE) == 0) return fail(ErrorKind::input, "part has no recorded size", part);
    if (st.size > max_bytes)
        return fail(ErrorKind::input, "part unpacks to " + std::to_string(st.size) + " bytes, above the limit of " +
                        std::to_string(max_bytes),
                    part);
    zip_file_t* file = zip_fopen(zip_.get(), part.c_str(), 0);
    if (!file) return fail(ErrorKind::input, std::string("cannot open part: ") + zip_strerror(zip_.get()), part);
    std::string out(static_cast<std::size_t>(st.size), '\0');
    std::size_t done = 0;
    while (done < out.size()) {
        const auto n = zip_fread(file, out.data() + done, out.size() - done);
        if (n < 0) {
            std::string why = zip_file_strerror(file);
            zip_fclose(file);
            return fail(ErrorKind::input, "corrupt part: " + why, part + ":byte " + std::to_string(done));
        }
        if (n == 0) break;
        done += static_cast<std::size_t>(n);
    }
    // Reading to the end makes libzip verify the CRC; one more read sees it.
    char extra = 0;
    const auto tail = zip_fread(file, &extra, 1);
    const bool crc_ok = tail == 0;
    std::string why = crc_ok ? std::string{} : zip_file_strerror(file);
    zip_fclose(file);
    if (done != out.size()) return fail(ErrorKind::input, "part is shorter than recorded", part + ":byte " + std::to_string(done));
    if (!crc_ok) return fail(ErrorKind::input, "corrupt part: " + (why.empty() ? std::string("data after end") : why), part);
    return out;
}

}  // namespace tactus::import::detail
