// The run hash: XXH64 over fixed little-endian event records (layout in hash.hpp).
#include "ricochet/hash.hpp"

#include <xxhash.h>

#include <cstring>

#include <fmt/format.h>

#include "ricochet/bits.hpp"

namespace ricochet {

namespace {
// Little-endian stores, independent of the host's byte order.
void put(unsigned char* p, std::uint64_t v, int bytes) {
    for (int i = 0; i < bytes; ++i) p[i] = static_cast<unsigned char>(v >> (8 * i));
}
}  // namespace

void encode_event(const Event& e, unsigned char (&r)[k_event_record_size]) {
    std::memset(r, 0, k_event_record_size);
    r[0] = static_cast<unsigned char>(e.kind);
    r[1] = static_cast<unsigned char>(e.shape);
    put(r + 4, e.ball, 4);
    put(r + 8, static_cast<std::uint64_t>(e.frame), 8);
    put(r + 16, e.index, 4);
    put(r + 24, bits_of(e.pos.x), 8);
    put(r + 32, bits_of(e.pos.y), 8);
    put(r + 40, bits_of(e.vel.x), 8);
    put(r + 48, bits_of(e.vel.y), 8);
}

RunHasher::RunHasher() : state_(XXH64_createState()) { XXH64_reset(static_cast<XXH64_state_t*>(state_), 0); }
RunHasher::~RunHasher() { XXH64_freeState(static_cast<XXH64_state_t*>(state_)); }

void RunHasher::flush() const {
    XXH64_update(static_cast<XXH64_state_t*>(state_), buffer_, used_);
    used_ = 0;
}

void RunHasher::add(const Event& event) {
    if (used_ + k_event_record_size > sizeof buffer_) flush();
    unsigned char record[k_event_record_size];
    encode_event(event, record);
    std::memcpy(buffer_ + used_, record, k_event_record_size);
    used_ += k_event_record_size;
}

void RunHasher::add(std::span<const Event> events) {
    for (const Event& e : events) add(e);
}

std::uint64_t RunHasher::digest() const {
    flush();
    return XXH64_digest(static_cast<const XXH64_state_t*>(state_));
}

std::uint64_t hash_events(std::span<const Event> events) {
    RunHasher h;
    h.add(events);
    return h.digest();
}

std::string format_hash(std::uint64_t hash) { return fmt::format("{:016x}", hash); }

std::optional<std::uint64_t> parse_hash(std::string_view text) {
    if (text.size() != 16) return std::nullopt;
    std::uint64_t v = 0;
    for (char c : text) {
        int d = 0;
        if (c >= '0' && c <= '9') d = c - '0';
        else if (c >= 'a' && c <= 'f') d = c - 'a' + 10;
        else return std::nullopt;
        v = (v << 4) | static_cast<std::uint64_t>(d);
    }
    return v;
}

}  // namespace ricochet
