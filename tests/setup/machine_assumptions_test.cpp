// What the setup leaves unsaid about the machine is assumed and said: the start, each axis's
// travel, the bar and its face. And the bar means the same from a setup's [stock] as from
// --stock: its face at Z0 unless stated.

#include "setup/machine_assumptions.hpp"

#include <gtest/gtest.h>

#include <variant>

#include "setup/setup.hpp"
#include "setup/stock_option.hpp"

namespace lathesim::setup {
namespace {

Setup parsed(std::string_view text) {
  SetupResult result = parseSetup(text, "part.toml");
  EXPECT_TRUE(result.setup.has_value());
  return result.setup ? *result.setup : defaultSetup();
}

sim::StockSpec stockOption(std::string_view text) {
  auto stock = parseStockOption(text);
  EXPECT_TRUE(std::holds_alternative<sim::StockSpec>(stock));
  return std::holds_alternative<sim::StockSpec>(stock) ? std::get<sim::StockSpec>(stock) : sim::StockSpec{};
}

void expectSameStock(const sim::StockSpec& a, const sim::StockSpec& b) {
  EXPECT_DOUBLE_EQ(a.diameterMm, b.diameterMm);
  EXPECT_DOUBLE_EQ(a.lengthMm, b.lengthMm);
  EXPECT_DOUBLE_EQ(a.faceZMm, b.faceZMm);
  EXPECT_DOUBLE_EQ(a.boreMm, b.boreMm);
}

TEST(StockRoutes, ASetupsStockAndTheStockOptionAreTheSameBar) {
  // Face unstated: Z0 by both routes (the default bar's Z2 is not a [stock]'s).
  expectSameStock(parsed("[stock]\ndiameter = 40\nlength = 80\n").stock, stockOption("D40xL80"));
  EXPECT_DOUBLE_EQ(parsed("[stock]\ndiameter = 40\nlength = 80\n").stock.faceZMm, 0.0);
  // Face stated: as stated by both.
  expectSameStock(parsed("[stock]\ndiameter = 40\nlength = 80\nface_z = 1.5\n").stock, stockOption("D40xL80xZ1.5"));
  expectSameStock(parsed("[stock]\ndiameter = 60\nlength = 80\nbore = 40\n").stock, stockOption("D60xd40xL80"));
  EXPECT_FALSE(stockOptionStatesFace("D40xL80"));
  EXPECT_FALSE(stockOptionStatesFace("D60xd40xL80"));
  EXPECT_TRUE(stockOptionStatesFace("D40xL80xZ1"));
  EXPECT_TRUE(stockOptionStatesFace("Z-1xD40xL80"));
}

TEST(MachineAssumptions, TheDefaultSetupAssumesEverything) {
  // Φ125 × 112, face Z2, start X200 Z200: travel X-125..X200, Z(2-112-112)..Z200.
  const auto assumed = machineAssumptions(defaultSetup());
  ASSERT_EQ(assumed.size(), 5u);
  EXPECT_EQ(assumed[0].key, "start");
  EXPECT_EQ(assumed[0].values, (std::vector<double>{200, 200}));
  EXPECT_EQ(assumed[1].key, "travel_x");
  EXPECT_EQ(assumed[1].values, (std::vector<double>{-125, 200}));
  EXPECT_EQ(assumed[2].key, "travel_z");
  EXPECT_EQ(assumed[2].values, (std::vector<double>{-222, 200}));
  EXPECT_EQ(assumed[3].key, "stock");
  EXPECT_EQ(assumed[3].values, (std::vector<double>{125, 112}));
  EXPECT_EQ(assumed[4].key, "stock_face_z");
  EXPECT_EQ(assumed[4].values, (std::vector<double>{2}));
  EXPECT_EQ(assumptionsText(assumed),
            "start X200 Z200, X travel X-125 to X200, Z travel Z-222 to Z200, bar Φ125 × 112, bar face at Z2");
}

TEST(MachineAssumptions, WhatTheSetupStatesIsNotAssumed) {
  const setup::Setup full = parsed(
      "[stock]\ndiameter = 40\nlength = 80\nface_z = 1\n[machine]\nstart = [100, 50]\ntravel_x = [-10, 300]\n"
      "travel_z = [-200, 300]\n");
  EXPECT_TRUE(machineAssumptions(full).empty());
  EXPECT_EQ(assumptionsText(machineAssumptions(full)), "");
  // Only the face left out: the face alone is assumed, at Z0.
  const setup::Setup noFace = parsed(
      "[stock]\ndiameter = 40\nlength = 80\n[machine]\nstart = [100, 50]\ntravel_x = [-10, 300]\n"
      "travel_z = [-200, 300]\n");
  const auto assumed = machineAssumptions(noFace);
  ASSERT_EQ(assumed.size(), 1u);
  EXPECT_EQ(assumed[0].key, "stock_face_z");
  EXPECT_EQ(assumed[0].values, (std::vector<double>{0}));
  // Only the start stated: the travel is derived from it and the bar.
  const setup::Setup startOnly = parsed("[stock]\ndiameter = 40\nlength = 80\nface_z = 0\n[machine]\nstart = [100, 50]\n");
  const auto derived = machineAssumptions(startOnly);
  ASSERT_EQ(derived.size(), 2u);
  EXPECT_EQ(derived[0].key, "travel_x");
  EXPECT_EQ(derived[0].values, (std::vector<double>{-40, 100}));
  EXPECT_EQ(derived[1].key, "travel_z");
  EXPECT_EQ(derived[1].values, (std::vector<double>{-160, 50}));
}

}  // namespace
}  // namespace lathesim::setup
