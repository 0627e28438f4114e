#include "audio/voice_pool.h"

#include <doctest/doctest.h>

using namespace ks::audio;

TEST_CASE("voice pool: free slots first, then the lowest priority voice is stolen") {
    VoicePool pool(3);
    const int a = pool.claim(1, 0.9f).slot, b = pool.claim(0, 0.9f).slot, c = pool.claim(2, 0.1f).slot;
    CHECK(pool.active_count() == 3);
    CHECK((a != b && b != c && a != c));
    const VoiceHandle old_b = pool.handle(b);

    const VoiceClaim claim = pool.claim(1, 0.5f);
    CHECK(claim.slot == b); // priority 0 is the least important, however loud
    CHECK(claim.stolen);
    CHECK(pool.find(old_b) == -1); // the stolen sound's handle is stale
    CHECK(pool.find(pool.handle(b)) == b);
    CHECK(pool.stolen() == 1);
    CHECK(pool.active_count() == 3);
}

TEST_CASE("voice pool: among equal priorities the quietest at the listener goes, then the oldest") {
    VoicePool pool(3);
    const int loud = pool.claim(5, 0.8f).slot;
    const int quiet = pool.claim(5, 0.2f).slot;
    const int mid = pool.claim(5, 0.5f).slot;
    CHECK(pool.claim(5, 0.3f).slot == quiet);
    // Gains change as the listener moves: the engine updates them every frame.
    pool.set_audible_gain(loud, 0.05f);
    CHECK(pool.claim(5, 0.3f).slot == loud);

    VoicePool same(3);
    const int first = same.claim(1, 0.5f).slot;
    const int second = same.claim(1, 0.5f).slot;
    same.claim(1, 0.5f);
    CHECK(same.claim(1, 0.5f).slot == first); // equal priority and gain: the oldest
    CHECK(same.claim(1, 0.5f).slot == second);
    (void)mid;
}

TEST_CASE("voice pool: a sound less important than every playing voice is dropped") {
    VoicePool pool(2);
    pool.claim(3, 0.5f);
    pool.claim(3, 0.4f);
    const VoiceClaim lower = pool.claim(2, 1.0f);
    CHECK(lower.slot == -1);
    CHECK_FALSE(lower.stolen);
    const VoiceClaim quieter = pool.claim(3, 0.3f);
    CHECK(quieter.slot == -1);
    CHECK(pool.dropped() == 2);
    CHECK(pool.stolen() == 0);
    CHECK(pool.claim(3, 0.4f).slot >= 0); // as loud as the quietest: the newer sound wins
    CHECK(pool.stolen() == 1);
}

TEST_CASE("voice pool: released slots are reused and old handles stay stale") {
    VoicePool pool(1);
    const int slot = pool.claim(0, 1.0f).slot;
    const VoiceHandle first = pool.handle(slot);
    CHECK(pool.find(first) == slot);
    pool.release(slot);
    CHECK(pool.active_count() == 0);
    CHECK(pool.find(first) == -1);
    pool.release(slot); // twice is harmless
    CHECK(pool.active_count() == 0);
    const VoiceClaim again = pool.claim(0, 1.0f);
    CHECK(again.slot == slot);
    CHECK_FALSE(again.stolen);
    CHECK(pool.find(first) == -1);
    CHECK(pool.find(VoiceHandle{}) == -1);
    CHECK(pool.find(VoiceHandle{7, 0}) == -1); // out of range
    CHECK(VoicePool(0).capacity() == 1);       // at least one voice
    CHECK(VoicePool().capacity() == VoicePool::kDefaultVoices);
}
