// The run hash: XXH64 (seed 0, libxxhash) over a fixed 56-byte little-endian record per event, in
// event order. Record layout, byte offsets:
//    0  u8   kind   (0 state, 1 hit, 2 overlap, 3 bump, 4 meet)
//    1  u8   shape  (0 none, 1 circle, 2 rect)
//    2  u16  zero
//    4  u32  ball
//    8  i64  frame  (two's complement)
//   16  u32  index  (hit: the wall; bump: the bumper; overlap: the circle or rect; meet: the other ball; state: 0)
//   20  u32  zero
//   24  u64  pos.x  IEEE-754 binary64 bit pattern (so -0 and +0 differ)
//   32  u64  pos.y
//   40  u64  vel.x  (meet: the velocity the ball leaves with; hit, bump and overlap: 0.0)
//   48  u64  vel.y
// Fields an event kind does not use are zero in Event and hashed as such.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "ricochet/scene.hpp"

namespace ricochet {

/// Bytes hashed per event (see the layout above).
inline constexpr std::size_t k_event_record_size = 56;

/// The event's 56-byte record (layout above).
void encode_event(const Event& event, unsigned char (&record)[k_event_record_size]);

/// Streaming run hash: add events in order, then digest.
class RunHasher {
public:
    /// An empty hash (XXH64, seed 0).
    RunHasher();
    /// Frees the XXH64 state.
    ~RunHasher();
    RunHasher(const RunHasher&) = delete;             ///< owns its state: not copyable
    RunHasher& operator=(const RunHasher&) = delete;  ///< owns its state: not copyable
    /// Adds one event's record.
    void add(const Event& event);
    /// Adds events in order.
    void add(std::span<const Event> events);
    /// The hash of everything added so far.
    std::uint64_t digest() const;

private:
    void flush() const;
    // Records are batched so XXH64_update sees 4 KiB at a time (a 56-byte update per event costs
    // more than the hashing itself); the digest is the same as hashing record by record.
    mutable unsigned char buffer_[k_event_record_size * 73];
    mutable std::size_t used_ = 0;
    void* state_;  // XXH64_state_t*
};

/// The run hash of events.
std::uint64_t hash_events(std::span<const Event> events);
/// 16 lowercase hex digits, zero-padded.
std::string format_hash(std::uint64_t hash);
/// Reads exactly 16 lowercase hex digits (what format_hash writes; docs/scene-log.md), or nothing.
std::optional<std::uint64_t> parse_hash(std::string_view text);

}  // namespace ricochet
