// The gallery's remote session without clients: off it does nothing, and its bookkeeping of which values
// a client set rather than the user decides what the settings file keeps. (With clients and a scene:
// tests/gpu/remote_link_test.cpp.)
#include <gtest/gtest.h>

#include "host/gallery/remote_session.h"

namespace vitrine::host {
namespace {

PanelEdit values(params::KeyValues pairs) { return PanelEdit{PanelEdit::What::Values, std::move(pairs), {}, {}}; }

TEST(RemoteSession, OffItListensToNobodyAndSaysNothing) {
  RemoteSession session;
  EXPECT_FALSE(session.on());
  EXPECT_EQ(session.port(), 0u);
  EXPECT_EQ(session.status(), "");
  EXPECT_FALSE(session.pointer({640, 360}));
  EXPECT_TRUE(session.takeActions().empty());
}

TEST(RemoteSession, WhatAClientSetIsNotTheUsersToSaveUntilTheUserSetsIt) {
  RemoteSession session;
  session.clientSet("kifs", "step");
  session.clientSet("kifs", "zoom");
  session.clientSet("noodles", "grid");
  EXPECT_EQ(session.notTheUsers("kifs"), (std::set<std::string>{"step", "zoom"}));
  EXPECT_EQ(session.notTheUsers("bloom"), std::set<std::string>{});
  session.userSet("kifs", values({{"zoom", "2"}}));  // the panel: zoom is the user's again
  EXPECT_EQ(session.notTheUsers("kifs"), std::set<std::string>{"step"});
  session.userSet("kifs", PanelEdit{PanelEdit::What::ResetAll, {}, {}, {}});  // everything is
  EXPECT_EQ(session.notTheUsers("kifs"), std::set<std::string>{});
  EXPECT_EQ(session.notTheUsers("noodles"), std::set<std::string>{"grid"});  // another scene's stay
}

TEST(RemoteSession, WithRemoteSavesEverythingIsTheUsersToSave) {
  RemoteSession session(/*saves=*/true);
  session.clientSet("kifs", "step");
  EXPECT_EQ(session.notTheUsers("kifs"), std::set<std::string>{});
}

TEST(RemoteSession, ListeningItSaysWhereInTheMenu) {
  RemoteSession session;
  session.listen("127.0.0.1:0", {}, nullptr);
  EXPECT_TRUE(session.on());
  EXPECT_NE(session.port(), 0u);
  EXPECT_NE(session.status().find("remote 127.0.0.1:"), std::string::npos) << session.status();
}

}  // namespace
}  // namespace vitrine::host
