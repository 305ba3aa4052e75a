#pragma once
// What the page does for the site that only a page can: downloads, its file picker, the browser's storage and its
// address. index.html holds the other half (the file input, dropping a file, the storage read back before main).

#include <string>

namespace impulse::web {

// Where the site's files are in the module's file system (the build packs them there): lessons/, scenes/.
inline constexpr const char* data_folder = "/impulse-lab";
// Where files the student picks or drops are written, by the page, before the site opens them.
inline constexpr const char* uploads_folder = "/uploads";
// Where the site writes the files it offers as downloads (a worksheet).
inline constexpr const char* downloads_folder = "/downloads";

// Offers a file of the module's file system as a download, named as the file.
void offer_download(const std::string& path);

// What a picked file is for.
enum class Pick { open = 0, progress = 1 };
// Opens the page's file picker; the file chosen comes back through impulse_file_picked (site.cpp).
void pick_file(Pick purpose);

// Keeps a copy of the file's text in the browser's storage (localStorage), under its path: the page writes it back
// before main runs, so it survives a reload and a closed tab.
void store(const std::string& path);

// The address's fragment ("#lesson=3", or empty), and a new one added to the history (Back returns to the last).
std::string fragment();
void set_fragment(const std::string& fragment);

// Tells the page the site is running (the page hides its loading line) or could not start.
void ready();
void failed(const std::string& why);

}  // namespace impulse::web
