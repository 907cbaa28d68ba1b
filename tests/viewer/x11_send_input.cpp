// Sends synthetic input to the viewer's window through the X server (XSendEvent), the way a
// user's keyboard and mouse reach GLFW, for the Xvfb tests:
//
//   x11_send_input TITLE_PART STEP...
//
// waits (up to 60 s) for a top-level window whose name contains TITLE_PART, then sends the steps
// back to back with one flush, so that key taps are far shorter than a frame:
//   key:NAME            press and release of the key (an X keysym name: 3, space, F1, Home)
//   move:X:Y            pointer motion to window coordinates (X, Y)
//   warp:X:Y            the real pointer moved there (XWarpPointer): what the toolkit reads when
//                       it asks where the pointer is (ImGui does), with the motion events it makes
//   press:B / release:B mouse button B (1 left, 3 right) at the last motion position
//   sleep:MS            flush, then wait MS milliseconds
//   close               the window manager's close request (WM_DELETE_WINDOW)
#include <X11/Xlib.h>
#include <X11/Xutil.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <thread>

namespace {

Window findWindow(Display* d, Window w, const char* titlePart) {
    char* name = nullptr;
    if (XFetchName(d, w, &name) && name) {
        const bool match = std::strstr(name, titlePart) != nullptr;
        XFree(name);
        if (match) return w;
    }
    Window root = 0, parent = 0, *children = nullptr;
    unsigned count = 0;
    Window found = 0;
    if (XQueryTree(d, w, &root, &parent, &children, &count)) {
        for (unsigned i = 0; i < count && !found; ++i) found = findWindow(d, children[i], titlePart);
        if (children) XFree(children);
    }
    return found;
}

struct Sender {
    Display* d;
    Window window;
    Window root;
    Time time = 1000;
    int x = 0, y = 0;

    // The fields every synthetic key, button and motion event shares.
    template <class Event>
    Event event(int type) {
        Event e{};
        e.type = type;
        e.display = d;
        e.window = window;
        e.root = root;
        e.time = time += 50;  // apart: GLFW reads a release and a press at the same time as a repeat
        e.x = x;
        e.y = y;
        e.same_screen = True;
        return e;
    }
    void key(const char* name, int type) {
        XKeyEvent e = event<XKeyEvent>(type);
        e.keycode = XKeysymToKeycode(d, XStringToKeysym(name));
        XSendEvent(d, window, True, type == KeyPress ? KeyPressMask : KeyReleaseMask, reinterpret_cast<XEvent*>(&e));
    }
    void button(unsigned b, int type) {
        XButtonEvent e = event<XButtonEvent>(type);
        e.button = b;
        XSendEvent(d, window, True, type == ButtonPress ? ButtonPressMask : ButtonReleaseMask,
                   reinterpret_cast<XEvent*>(&e));
    }
    void motion(int nx, int ny) {
        x = nx;
        y = ny;
        XMotionEvent e = event<XMotionEvent>(MotionNotify);
        XSendEvent(d, window, True, PointerMotionMask, reinterpret_cast<XEvent*>(&e));
    }
    void close() {
        XClientMessageEvent e{};
        e.type = ClientMessage;
        e.window = window;
        e.message_type = XInternAtom(d, "WM_PROTOCOLS", False);
        e.format = 32;
        e.data.l[0] = long(XInternAtom(d, "WM_DELETE_WINDOW", False));
        e.data.l[1] = CurrentTime;
        XSendEvent(d, window, False, NoEventMask, reinterpret_cast<XEvent*>(&e));
    }
};

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: x11_send_input TITLE_PART STEP...\n");
        return 2;
    }
    Display* d = XOpenDisplay(nullptr);
    if (!d) {
        std::fprintf(stderr, "x11_send_input: no X display\n");
        return 2;
    }
    const Window root = DefaultRootWindow(d);
    Window window = 0;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (!(window = findWindow(d, root, argv[1]))) {
        if (std::chrono::steady_clock::now() > deadline) {
            std::fprintf(stderr, "x11_send_input: no window named '*%s*' within 60 s\n", argv[1]);
            return 1;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    Sender s{d, window, root};
    for (int i = 2; i < argc; ++i) {
        const std::string step = argv[i];
        int a = 0, b = 0;
        if (step.rfind("key:", 0) == 0) {
            s.key(step.c_str() + 4, KeyPress);
            s.key(step.c_str() + 4, KeyRelease);
        } else if (std::sscanf(step.c_str(), "move:%d:%d", &a, &b) == 2) {
            s.motion(a, b);
        } else if (std::sscanf(step.c_str(), "warp:%d:%d", &a, &b) == 2) {
            XWarpPointer(d, None, window, 0, 0, 0, 0, a, b);
            s.x = a;
            s.y = b;
        } else if (std::sscanf(step.c_str(), "press:%d", &a) == 1) {
            s.button(unsigned(a), ButtonPress);
        } else if (std::sscanf(step.c_str(), "release:%d", &a) == 1) {
            s.button(unsigned(a), ButtonRelease);
        } else if (std::sscanf(step.c_str(), "sleep:%d", &a) == 1) {
            XFlush(d);
            std::this_thread::sleep_for(std::chrono::milliseconds(a));
        } else if (step == "close") {
            s.close();
        } else {
            std::fprintf(stderr, "x11_send_input: unknown step '%s'\n", step.c_str());
            return 2;
        }
    }
    XFlush(d);
    XCloseDisplay(d);
    return 0;
}
