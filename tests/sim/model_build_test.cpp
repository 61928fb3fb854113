// Spring builds that gather their own inputs: where the gathering runs, and
// waiting for a build without taking it.
#include "sim/model_build.h"

#include <gtest/gtest.h>

#include <atomic>
#include <thread>

namespace mtcut::sim {
namespace {

// One tet's inputs, gathered by the caller's function.
ModelInputs one_tet() {
  ModelInputs in;
  in.tets = {engine::Tet{VertId(0), VertId(1), VertId(2), VertId(3)}};
  in.rest_positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  return in;
}

TEST(ModelBuild, GathersItsInputsOnTheWorker) {
  WorkerThread worker;
  std::thread::id gathered_on;
  ModelBuild build(
      [&] {
        gathered_on = std::this_thread::get_id();
        return one_tet();
      },
      &worker);
  const SpringModel model = build.take();
  EXPECT_EQ(gathered_on, worker.id());
  EXPECT_EQ(model.num_particles(), 4u);
  EXPECT_EQ(model.num_springs(), 6u);
  EXPECT_TRUE(model.validate().ok());
}

TEST(ModelBuild, WithoutAWorkerGathersWhenTakenOnTheTakersThread) {
  std::atomic<int> gathered{0};
  std::thread::id gathered_on;
  ModelBuild build(
      [&] {
        ++gathered;
        gathered_on = std::this_thread::get_id();
        return one_tet();
      },
      nullptr);
  build.wait();  // a build left for the taker does not run on wait()
  EXPECT_EQ(gathered.load(), 0);
  EXPECT_EQ(build.take().num_springs(), 6u);
  EXPECT_EQ(gathered.load(), 1);
  EXPECT_EQ(gathered_on, std::this_thread::get_id());
}

TEST(ModelBuild, WaitReturnsOnceTheWorkersBuildRan) {
  WorkerThread worker;
  std::atomic<bool> release{false}, gathered{false};
  // The first job holds the worker until released: the build queued after it cannot have run.
  auto hold = worker.submit([&] {
    while (!release.load()) std::this_thread::yield();
    return 0;
  });
  ModelBuild build(
      [&] {
        gathered = true;
        return one_tet();
      },
      &worker);
  EXPECT_FALSE(gathered.load());
  release = true;
  build.wait();
  EXPECT_TRUE(gathered.load());
  EXPECT_EQ(hold.get(), 0);
  EXPECT_EQ(build.take().num_particles(), 4u) << "wait() does not take the model";
}

// wait() on a future with no state throws (std::future_error).
TEST(ModelBuild, AnEmptyBuildWaitsForNothing) {
  const ModelBuild none;
  EXPECT_NO_THROW(none.wait());
}

}  // namespace
}  // namespace mtcut::sim
