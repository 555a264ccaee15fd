// The machine: its options (defaults, what it refuses), home switches and axis positions on a
// hand-made model.
#include "volcomp/sim/machine.hpp"

#include <gtest/gtest.h>

#include <string>

#include "sim_machines.hpp"

namespace volcomp::sim {
namespace {

using volcomp::testing::LinearErrorModel;
using volcomp::testing::MachineOf;

TEST(SimMachine, HomeSwitchAndAxisPositions) {
  Machine machine =
      MachineOf(LinearErrorModel());  // power-up 10 % into 0..100, switch 5 mm below 0
  EXPECT_DOUBLE_EQ(machine.power_up_mm(0), 10);
  EXPECT_DOUBLE_EQ(machine.home_switch_mm(0), -5);
  EXPECT_FALSE(machine.HomeSwitchClosed(0, -14999));
  EXPECT_TRUE(machine.HomeSwitchClosed(0, -15000));
  const model::Vec3 q = machine.AxisPositions_mm({1000, -2000, 0});
  EXPECT_NEAR(q.x, 11, 1e-12);
  EXPECT_NEAR(q.y, 8, 1e-12);
  EXPECT_NEAR(q.z, 10, 1e-12);
}

TEST(SimMachine, RefusesOptionsNoMachineHas) {
  MachineOptions step;
  step.model = LinearErrorModel();
  step.step_mm[1] = 0;
  const Expected<Machine> no_step = Machine::Create(step);
  ASSERT_FALSE(no_step.ok());
  EXPECT_EQ(no_step.error().code, Error::kInvalidArgument);
  EXPECT_EQ(no_step.error().message, "machine: step length must be > 0");

  MachineOptions below;
  below.model = LinearErrorModel();
  below.power_up_mm = {10, 10, -6};  // below Z's switch at -5 mm
  const Expected<Machine> on_switch = Machine::Create(below);
  ASSERT_FALSE(on_switch.ok());
  EXPECT_EQ(on_switch.error().message, "machine: the axes must power up above their home switches");

  MachineOptions formulation;
  formulation.model = LinearErrorModel();
  formulation.model.formulation = model::Formulation::kDissertation;
  const Expected<Machine> dissertation = Machine::Create(formulation);
  ASSERT_FALSE(dissertation.ok());
  EXPECT_NE(dissertation.error().message.find("the simulated machine is a rigid body"),
            std::string::npos);

  MachineOptions chain;
  chain.model = LinearErrorModel();
  chain.model.chain.order = {0, 0, 2};  // ValidateModel's refusal, as a failure
  const Expected<Machine> bad_chain = Machine::Create(chain);
  ASSERT_FALSE(bad_chain.ok());
  EXPECT_EQ(bad_chain.error().code, Error::kInvalidArgument);
  EXPECT_FALSE(bad_chain.error().message.empty());
}

TEST(SimMachine, DefaultsToTheS500AndLoadsModelFiles) {
  const Expected<Machine> s500 = Machine::Create(MachineOptions{});
  ASSERT_TRUE(s500.ok()) << s500.error().message;
  EXPECT_DOUBLE_EQ(s500->travel_max_mm(0), 400);
  const Expected<model::Model> builtin = LoadMachineModel("s500");
  ASSERT_TRUE(builtin.ok());
  EXPECT_EQ(builtin->name, s500->model().name);
  const Expected<model::Model> missing = LoadMachineModel("/nonexistent/machine.conf");
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.error().message.find("/nonexistent/machine.conf"), std::string::npos)
      << missing.error().message;
}

}  // namespace
}  // namespace volcomp::sim
