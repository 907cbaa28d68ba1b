#include "file_panel.h"

#include "widgets.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <filesystem>

namespace shadowlab::ui {

void FileUi::remember(const std::string& file) {
    recent.erase(std::remove(recent.begin(), recent.end(), file), recent.end());
    recent.push_front(file);
    while (recent.size() > kMaxRecent) recent.pop_back();
}

std::vector<BrowseEntry> browseEntries(const std::string& dir) {
    namespace fs = std::filesystem;
    std::vector<BrowseEntry> entries;
    std::error_code ec;
    fs::directory_iterator it(dir.empty() ? fs::path(".") : fs::path(dir), fs::directory_options::skip_permission_denied, ec);
    constexpr std::size_t kMaxEntries = 2000;  // a huge folder is listed in part, not frozen on
    for (; !ec && it != fs::directory_iterator() && entries.size() < kMaxEntries; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name.empty() || name[0] == '.') continue;
        std::error_code typeError;
        if (it->is_directory(typeError)) {
            entries.push_back({name, true});
            continue;
        }
        std::string ext = it->path().extension().string();
        std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
        if (ext == ".gltf" || ext == ".glb" || ext == ".json" || ext == ".png") entries.push_back({name, false});
    }
    std::sort(entries.begin(), entries.end(), [](const BrowseEntry& a, const BrowseEntry& b) {
        return a.folder != b.folder ? a.folder : a.name < b.name;
    });
    return entries;
}

namespace {

// The browser's list; returns the file picked, or "".
std::string drawBrowser(FileUi& ui) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path dir = fs::absolute(ui.browseDir.empty() ? fs::path(".") : fs::path(ui.browseDir), ec).lexically_normal();
    ImGui::TextWrapped("%s", dir.string().c_str());
    std::string picked;
    if (ImGui::BeginChild("##browser", ImVec2(0.0f, 180.0f), true)) {
        if (dir.has_parent_path() && dir != dir.root_path() && ImGui::Selectable("../")) ui.browseDir = dir.parent_path().string();
        for (const BrowseEntry& e : browseEntries(dir.string())) {
            const std::string label = e.folder ? e.name + "/" : e.name;
            if (!ImGui::Selectable(label.c_str())) continue;
            if (e.folder) ui.browseDir = (dir / e.name).string();
            else picked = (dir / e.name).string();
        }
    }
    ImGui::EndChild();
    return picked;
}

}  // namespace

std::string drawFilePanel(FileUi& ui) {
    std::string open;
    const bool entered =
        ImGui::InputText("path##open", ui.path, sizeof ui.path, ImGuiInputTextFlags_EnterReturnsTrue);
    tip("A scene (.gltf, .glb), a view state (.json) or a screenshot saved by shadowlab (.png, its settings are "
        "embedded). A scene that fails to load leaves the current one on screen. Dropping a file on the window "
        "does the same.");
    ImGui::SameLine();
    if ((ImGui::Button("open") || entered) && ui.path[0] != '\0') open = ui.path;
    ImGui::SameLine();
    if (ImGui::Button(ui.browsing ? "close browser" : "browse...")) ui.browsing = !ui.browsing;
    if (ui.browsing) {
        const std::string picked = drawBrowser(ui);
        if (!picked.empty()) {
            open = picked;
            std::snprintf(ui.path, sizeof ui.path, "%s", picked.c_str());
        }
    }
    if (!ui.recent.empty()) {
        ImGui::TextDisabled("recent:");
        for (std::size_t i = 0; i < ui.recent.size(); ++i) {
            const std::string& f = ui.recent[i];
            const std::string label = f + "##recent" + std::to_string(i);
            if (ImGui::Selectable(label.c_str())) open = f;
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", f.c_str());
        }
    }
    return open;
}

}  // namespace shadowlab::ui
