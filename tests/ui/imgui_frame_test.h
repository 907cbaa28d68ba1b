#pragma once
// An ImGui context without any renderer backend (no display, no GL), for the panel tests: the
// font atlas is built, nothing is uploaded; frame() runs one NewFrame .. Render.
#include <gtest/gtest.h>
#include <imgui.h>

namespace shadowlab::ui {

class ImGuiFrameTest : public ::testing::Test {
protected:
    void SetUp() override {
        ImGui::CreateContext();
        ImGuiIO& io = ImGui::GetIO();
        io.IniFilename = nullptr;
        io.DisplaySize = ImVec2(1280, 720);
        io.DeltaTime = 1.0f / 60.0f;
        unsigned char* pixels = nullptr;
        int w = 0, h = 0;
        io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);  // builds the atlas; no texture upload needed
    }
    void TearDown() override { ImGui::DestroyContext(); }

    template <class Draw>
    void frame(Draw&& draw) {
        ImGui::NewFrame();
        draw();
        ImGui::Render();
        ASSERT_NE(ImGui::GetDrawData(), nullptr);
    }
};

}  // namespace shadowlab::ui
