// SPDX-License-Identifier: GPL-3.0-or-later
// The job's bytes: fixed-width little-endian integers, strings and lists as a
// 64-bit length and their contents.
#include "pipeline/translation_job.hpp"

#include <cstdint>
#include <limits>

namespace tactus::pipeline {
namespace {

constexpr std::string_view kMark = "tactus translation job\n";

class Writer {
public:
    void u8(std::uint8_t v) { out.push_back(static_cast<char>(v)); }
    void u64(std::uint64_t v) {
        for (int i = 0; i < 8; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xFFu));
    }
    void i32(int v) { u64(static_cast<std::uint64_t>(static_cast<std::int64_t>(v))); }
    void flag(bool v) { u8(v ? 1 : 0); }
    void bytes(std::string_view s) {
        u64(s.size());
        out.append(s);
    }
    void cells(const document::BrailleLine& line) {
        u64(line.size());
        for (const auto c : line) u8(c.dots);
    }
    std::string out;
};

class Reader {
public:
    Reader(std::string_view in, std::size_t from) : in_(in), pos_(from) {}

    bool u8(std::uint8_t& v) {
        if (!need(1)) return false;
        v = static_cast<std::uint8_t>(in_[pos_++]);
        return true;
    }
    bool u64(std::uint64_t& v) {
        if (!need(8)) return false;
        v = 0;
        for (int i = 0; i < 8; ++i) v |= std::uint64_t{static_cast<std::uint8_t>(in_[pos_++])} << (8 * i);
        return true;
    }
    bool i32(int& v) {
        std::uint64_t u = 0;
        if (!u64(u)) return false;
        const auto s = static_cast<std::int64_t>(u);
        if (s < std::numeric_limits<int>::min() || s > std::numeric_limits<int>::max()) return bad("a number out of range");
        v = static_cast<int>(s);
        return true;
    }
    bool flag(bool& v) {
        std::uint8_t u = 0;
        if (!u8(u)) return false;
        if (u > 1) return bad("a flag that is neither 0 nor 1");
        v = u == 1;
        return true;
    }
    // An enumeration stored as its byte, at most `last`.
    template <typename E>
    bool enumerated(E& v, E last) {
        std::uint8_t u = 0;
        if (!u8(u)) return false;
        if (u > static_cast<std::uint8_t>(last)) return bad("an unknown kind " + std::to_string(u));
        v = static_cast<E>(u);
        return true;
    }
    bool bytes(std::string& s) {
        std::uint64_t n = 0;
        if (!count(n, 1)) return false;
        s.assign(in_.substr(pos_, n));
        pos_ += n;
        return true;
    }
    bool cells(document::BrailleLine& line) {
        std::uint64_t n = 0;
        if (!count(n, 1)) return false;
        line.resize(n);
        for (auto& c : line) c.dots = static_cast<std::uint8_t>(in_[pos_++]);
        return true;
    }
    // A list's length, refused when its items (each at least `least` bytes)
    // cannot fit in what is left: a length that is wrong fails here, before
    // anything is allocated for it.
    bool count(std::uint64_t& n, std::size_t least) {
        if (!u64(n)) return false;
        if (n > (in_.size() - pos_) / least) return bad("a length of " + std::to_string(n) + " past the end");
        return true;
    }
    bool at_end() const { return pos_ == in_.size(); }
    bool bad(std::string why) {
        if (why_.empty()) {
            why_ = std::move(why);
            where_ = pos_;
        }
        return false;
    }
    Error error() const {
        return Error{"a translation job this program cannot read: " + (why_.empty() ? std::string("cut short") : why_),
                     "byte " + std::to_string(why_.empty() ? in_.size() : where_), ErrorKind::internal};
    }

private:
    bool need(std::size_t n) { return in_.size() - pos_ >= n; }
    std::string_view in_;
    std::size_t pos_ = 0;
    std::string why_;
    std::size_t where_ = 0;
};

void write_block(Writer& w, const document::Block& b) {
    w.u8(static_cast<std::uint8_t>(b.kind));
    w.i32(b.level);
    w.u64(b.spans.size());
    for (const auto& s : b.spans) {
        w.bytes(s.text);
        w.u8(s.emphasis);
        w.flag(s.note_reference);
        w.u8(static_cast<std::uint8_t>(s.position));
        w.flag(s.transcriber_note);
        w.bytes(s.language);
    }
    w.u64(b.braille_lines.size());
    for (const auto& line : b.braille_lines) w.cells(line);
    w.bytes(b.label);
    w.flag(b.label_counted);
    w.i32(b.source_line);
    w.i32(b.span);
    w.u8(static_cast<std::uint8_t>(b.align));
    w.i32(b.box);
    w.u64(b.images.size());
    for (const auto& image : b.images) {
        w.bytes(image.bytes);
        w.bytes(image.media_type);
        w.bytes(image.name);
    }
}

bool read_block(Reader& r, document::Block& b) {
    std::uint64_t n = 0;
    if (!r.enumerated(b.kind, document::BlockKind::table_cell) || !r.i32(b.level) || !r.count(n, 8)) return false;
    b.spans.resize(n);
    for (auto& s : b.spans)
        if (!r.bytes(s.text) || !r.u8(s.emphasis) || !r.flag(s.note_reference) ||
            !r.enumerated(s.position, document::Position::subscript) || !r.flag(s.transcriber_note) ||
            !r.bytes(s.language))
            return false;
    if (!r.count(n, 8)) return false;
    b.braille_lines.resize(n);
    for (auto& line : b.braille_lines)
        if (!r.cells(line)) return false;
    if (!r.bytes(b.label) || !r.flag(b.label_counted) || !r.i32(b.source_line) || !r.i32(b.span) ||
        !r.enumerated(b.align, document::Align::right) || !r.i32(b.box) || !r.count(n, 24))
        return false;
    b.images.resize(n);
    for (auto& image : b.images)
        if (!r.bytes(image.bytes) || !r.bytes(image.media_type) || !r.bytes(image.name)) return false;
    return true;
}

}  // namespace

std::string serialize(const TranslationJob& job) {
    Writer w;
    w.out.append(kMark);
    w.bytes(job.tables);
    w.flag(job.language.enabled);
    w.bytes(job.language.second_table);
    w.bytes(job.language.english_grade);
    w.u8(static_cast<std::uint8_t>(job.language.indicators));
    w.bytes(job.source_name);
    w.u64(job.blocks.size());
    for (std::size_t i = 0; i < job.blocks.size(); ++i) {
        write_block(w, job.blocks[i]);
        w.u64(i < job.word_rooms.size() ? job.word_rooms[i] : 0);
    }
    return std::move(w.out);
}

Result<TranslationJob> parse_translation_job(std::string_view bytes) {
    if (!bytes.starts_with(kMark))
        return fail(ErrorKind::internal, "not a translation job: it does not begin with its mark", "byte 0");
    Reader r(bytes, kMark.size());
    TranslationJob job;
    std::uint64_t n = 0;
    const auto located_error = [&r] { return std::unexpected(r.error()); };
    if (!r.bytes(job.tables) || !r.flag(job.language.enabled) || !r.bytes(job.language.second_table) ||
        !r.bytes(job.language.english_grade) ||
        !r.enumerated(job.language.indicators, translate::SwitchIndicators::none) || !r.bytes(job.source_name) ||
        !r.count(n, 1))
        return located_error();
    job.blocks.resize(n);
    job.word_rooms.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        std::uint64_t room = 0;
        if (!read_block(r, job.blocks[i]) || !r.u64(room)) return located_error();
        job.word_rooms[i] = static_cast<std::size_t>(room);
    }
    if (!r.at_end()) {
        r.bad("bytes after the last block");
        return located_error();
    }
    return job;
}

}  // namespace tactus::pipeline
