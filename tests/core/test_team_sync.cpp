// The team's waits (core/team_sync.hpp): the barrier runs its serial part once
// per round, on the last thread to arrive, after every thread's work of that
// round and before any thread's work of the next; wait_for_value returns only
// once the awaited value is there, also after sleeping. Run with more threads
// than the machine has cores, so that threads are descheduled mid-round.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

#include "talus/core/team_sync.hpp"

using namespace talus;

TEST(TeamBarrier, SerialPartRunsOncePerRoundBetweenTheRounds) {
  constexpr int team = 5, rounds = 2000;
  TeamBarrier barrier;
  barrier.reset(team);
  std::atomic<int> work{0};
  int serial_runs = 0;  // touched by the serial part only
  std::atomic<int> bad{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < team; ++t)
    threads.emplace_back([&] {
      for (int r = 0; r < rounds; ++r) {
        // Work of round r: nobody may be here before round r - 1's serial part.
        if (serial_runs != r) bad.fetch_add(1);
        work.fetch_add(1);
        barrier.arrive_and_wait([&] {
          if (work.load() != team * (r + 1)) bad.fetch_add(1);
          ++serial_runs;
        });
      }
    });
  for (auto& t : threads) t.join();
  EXPECT_EQ(serial_runs, rounds);
  EXPECT_EQ(work.load(), team * rounds);
  EXPECT_EQ(bad.load(), 0);
}

TEST(WaitForValue, ReturnsAfterALateStore) {
  std::atomic<uint32_t> flag{0};
  std::thread late([&] {
    // Far longer than the spin: the waiter is asleep when the value comes.
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    flag.store(1);  // a value that is not awaited: the waiter must go on waiting
    flag.notify_all();
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    flag.store(7);
    flag.notify_all();
  });
  wait_for_value(flag, 7u);
  EXPECT_EQ(flag.load(), 7u);
  late.join();
}
