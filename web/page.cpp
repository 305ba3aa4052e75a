#include "web/page.hpp"

#include <emscripten/emscripten.h>

#include <cstdlib>

namespace impulse::web {

namespace {

// The JavaScript halves, as written (clang-format would take them for C++).
// clang-format off
EM_JS(void, js_offer_download, (const char* path), {
    const name = UTF8ToString(path);
    // Read past the file's mode bits, as js_store does; a file that cannot be read is an error the page reports.
    const permissions = FS.ignorePermissions;
    FS.ignorePermissions = true;
    let bytes;
    try {
        bytes = FS.readFile(name);
    } catch (e) {
        console.error("impulse-lab: cannot offer " + name + " as a download: " + e);
        return;
    } finally {
        FS.ignorePermissions = permissions;
    }
    const url = URL.createObjectURL(new Blob([bytes], {
        type:
            "application/octet-stream"
    }));
    const link = document.createElement("a");
    link.href = url;
    link.download = name.substring(name.lastIndexOf("/") + 1);
    document.body.appendChild(link);
    link.click();
    link.remove();
    setTimeout(function() { URL.revokeObjectURL(url); }, 60000);
});

EM_JS(void, js_pick_file, (int purpose), {
    const input = document.getElementById("file");
    input.dataset.purpose = String(purpose);
    input.value = "";
    input.click();
});

EM_JS(void, js_store, (const char* path), {
    const name = UTF8ToString(path);
    // The module's files are the page's own: read past their mode bits (emscripten 3.1.6's umask leaves a file the
    // atomic writer made without them).
    const permissions = FS.ignorePermissions;
    FS.ignorePermissions = true;
    try {
        localStorage.setItem("impulse-lab:" + name, FS.readFile(name, {encoding: "utf8"}));
    } catch (e) {
        console.warn("impulse-lab: the browser keeps no storage for this page: " + e);
    } finally {
        FS.ignorePermissions = permissions;
    }
});

EM_JS(char*, js_fragment, (), {
    const text = window.location.hash || "";
    const size = lengthBytesUTF8(text) + 1;
    const memory = _malloc(size);
    stringToUTF8(text, memory, size);
    return memory;
});

EM_JS(void, js_set_fragment, (const char* text), {
    const fragment = UTF8ToString(text);
    if ((window.location.hash || "") == fragment) return;
    history.pushState(null, "", fragment == "" ? window.location.pathname + window.location.search : fragment);
});

EM_JS(void, js_ready, (), {
    if (Module.onSiteReady) Module.onSiteReady();
});

EM_JS(void, js_failed, (const char* why), {
    if (Module.onSiteFailed) Module.onSiteFailed(UTF8ToString(why));
});
// clang-format on

}  // namespace

void offer_download(const std::string& path) {
    js_offer_download(path.c_str());
}

void pick_file(Pick purpose) {
    js_pick_file(static_cast<int>(purpose));
}

void store(const std::string& path) {
    js_store(path.c_str());
}

std::string fragment() {
    char* text = js_fragment();
    std::string result(text);
    std::free(text);
    return result;
}

void set_fragment(const std::string& text) {
    js_set_fragment(text.c_str());
}

void ready() {
    js_ready();
}

void failed(const std::string& why) {
    js_failed(why.c_str());
}

}  // namespace impulse::web
