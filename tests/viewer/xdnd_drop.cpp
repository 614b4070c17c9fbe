// xdnd_drop TITLE FILE [--shot OUT.png] [--wait SECONDS] [--expect-title TEXT]
//
// A user dragging FILE from a file manager onto the X window whose title
// starts with TITLE, for the viewer's drop test under Xvfb: the XDND
// protocol (version 5) from the source side: XdndEnter offering
// text/uri-list, XdndPosition at the window's centre, XdndDrop once it
// accepts, the file's URI when it asks for the selection, until
// XdndFinished. Then, after --wait seconds, it checks that the window's
// title reads --expect-title and writes the window's pixels to --shot.
// Exit 0 on success; 1 with the reason on stderr.
#include <X11/Xatom.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <poll.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <thread>

#include "viewer/png.hpp"

namespace {

Display* dpy = nullptr;

std::string name_of(Window w) {
  Atom utf8 = XInternAtom(dpy, "UTF8_STRING", False), net_name = XInternAtom(dpy, "_NET_WM_NAME", False);
  Atom type;
  int format;
  unsigned long n, after;
  unsigned char* data = nullptr;
  std::string name;
  if (XGetWindowProperty(dpy, w, net_name, 0, 1024, False, utf8, &type, &format, &n, &after, &data) == Success &&
      data) {
    name.assign(reinterpret_cast<char*>(data), n);
    XFree(data);
    return name;
  }
  char* wm = nullptr;
  if (XFetchName(dpy, w, &wm) && wm) {
    name = wm;
    XFree(wm);
  }
  return name;
}

Window find(Window w, const std::string& prefix) {
  if (name_of(w).rfind(prefix, 0) == 0) return w;
  Window root, parent, *children = nullptr;
  unsigned int n = 0;
  if (!XQueryTree(dpy, w, &root, &parent, &children, &n)) return 0;
  Window found = 0;
  for (unsigned int i = 0; i < n && !found; ++i) found = find(children[i], prefix);
  if (children) XFree(children);
  return found;
}

// The next event, or false after `ms`.
bool next_event(XEvent& e, int ms) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::milliseconds(ms);
  while (!XPending(dpy)) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(end - std::chrono::steady_clock::now());
    if (left.count() <= 0) return false;
    pollfd p{ConnectionNumber(dpy), POLLIN, 0};
    poll(&p, 1, static_cast<int>(left.count()));
  }
  XNextEvent(dpy, &e);
  return true;
}

int fail(const std::string& why) {
  std::fprintf(stderr, "xdnd_drop: %s\n", why.c_str());
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) return fail("usage: xdnd_drop TITLE FILE [--shot OUT.png] [--wait S] [--expect-title TEXT]");
  const std::string title = argv[1];
  const std::string file = std::filesystem::absolute(argv[2]).string();
  std::string shot, expect;
  double wait_s = 0;
  for (int i = 3; i + 1 < argc; i += 2) {
    const std::string k = argv[i];
    if (k == "--shot") shot = argv[i + 1];
    else if (k == "--wait") wait_s = std::atof(argv[i + 1]);
    else if (k == "--expect-title") expect = argv[i + 1];
  }
  dpy = XOpenDisplay(nullptr);
  if (!dpy) return fail("no X display");
  const Window root = DefaultRootWindow(dpy);
  Window target = 0;
  for (int i = 0; i < 300 && !target; ++i) {
    target = find(root, title);
    if (!target) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  if (!target) return fail("no window titled \"" + title + "...\"");

  const Atom aware = XInternAtom(dpy, "XdndAware", False), enter = XInternAtom(dpy, "XdndEnter", False),
             position = XInternAtom(dpy, "XdndPosition", False), status = XInternAtom(dpy, "XdndStatus", False),
             drop = XInternAtom(dpy, "XdndDrop", False), finished = XInternAtom(dpy, "XdndFinished", False),
             selection = XInternAtom(dpy, "XdndSelection", False), copy = XInternAtom(dpy, "XdndActionCopy", False),
             uri_list = XInternAtom(dpy, "text/uri-list", False);
  {
    Atom type;
    int format;
    unsigned long n, after;
    unsigned char* data = nullptr;
    if (XGetWindowProperty(dpy, target, aware, 0, 1, False, AnyPropertyType, &type, &format, &n, &after, &data) !=
            Success || !data)
      return fail("the window does not accept drops (no XdndAware)");
    XFree(data);
  }
  const Window source = XCreateSimpleWindow(dpy, root, 0, 0, 1, 1, 0, 0, 0);
  XSetSelectionOwner(dpy, selection, source, CurrentTime);

  auto send = [&](Atom type, long l1, long l2, long l3, long l4) {
    XEvent e{};
    e.xclient.type = ClientMessage;
    e.xclient.window = target;
    e.xclient.message_type = type;
    e.xclient.format = 32;
    e.xclient.data.l[0] = static_cast<long>(source);
    e.xclient.data.l[1] = l1;
    e.xclient.data.l[2] = l2;
    e.xclient.data.l[3] = l3;
    e.xclient.data.l[4] = l4;
    XSendEvent(dpy, target, False, NoEventMask, &e);
    XFlush(dpy);
  };
  XWindowAttributes a{};
  XGetWindowAttributes(dpy, target, &a);
  int cx = 0, cy = 0;
  Window child;
  XTranslateCoordinates(dpy, target, root, a.width / 2, a.height / 2, &cx, &cy, &child);

  send(enter, 5L << 24, static_cast<long>(uri_list), 0, 0);
  send(position, 0, (static_cast<long>(cx) << 16) | cy, CurrentTime, static_cast<long>(copy));
  bool accepted = false, done = false;
  const std::string uri = "file://" + file + "\r\n";
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (!done && std::chrono::steady_clock::now() < end) {
    XEvent e;
    if (!next_event(e, 200)) continue;
    if (e.type == ClientMessage && e.xclient.message_type == status && !accepted) {
      if (!(e.xclient.data.l[1] & 1)) return fail("the window refused the drop");
      accepted = true;
      send(drop, 0, CurrentTime, 0, 0);
    } else if (e.type == SelectionRequest) {
      const XSelectionRequestEvent& r = e.xselectionrequest;
      XEvent reply{};
      reply.xselection.type = SelectionNotify;
      reply.xselection.requestor = r.requestor;
      reply.xselection.selection = r.selection;
      reply.xselection.target = r.target;
      reply.xselection.time = r.time;
      reply.xselection.property = None;
      if (r.target == uri_list) {
        XChangeProperty(dpy, r.requestor, r.property, uri_list, 8, PropModeReplace,
                        reinterpret_cast<const unsigned char*>(uri.data()), static_cast<int>(uri.size()));
        reply.xselection.property = r.property;
      }
      XSendEvent(dpy, r.requestor, False, NoEventMask, &reply);
      XFlush(dpy);
    } else if (e.type == ClientMessage && e.xclient.message_type == finished) {
      done = true;
    }
  }
  if (!accepted) return fail("no XdndStatus from the window");
  if (!done) return fail("no XdndFinished from the window");
  std::printf("dropped %s\n", file.c_str());

  if (wait_s > 0) std::this_thread::sleep_for(std::chrono::duration<double>(wait_s));
  if (!expect.empty() && name_of(target) != expect)
    return fail("the window's title is \"" + name_of(target) + "\", not \"" + expect + "\"");
  if (!shot.empty()) {
    XGetWindowAttributes(dpy, target, &a);
    XImage* img = XGetImage(dpy, target, 0, 0, static_cast<unsigned>(a.width), static_cast<unsigned>(a.height),
                            AllPlanes, ZPixmap);
    if (!img) return fail("cannot read the window's pixels");
    mc::viewer::Image out(a.width, a.height);
    for (int y = 0; y < a.height; ++y)
      for (int x = 0; x < a.width; ++x) {
        const unsigned long p = XGetPixel(img, x, y);
        out.set(x, y, static_cast<std::uint8_t>((p & img->red_mask) >> 16),
                static_cast<std::uint8_t>((p & img->green_mask) >> 8), static_cast<std::uint8_t>(p & img->blue_mask));
      }
    XDestroyImage(img);
    std::string error;
    if (!mc::viewer::write_png(shot, out, error)) return fail(error);
    std::printf("wrote %s (%dx%d)\n", shot.c_str(), a.width, a.height);
  }
  XCloseDisplay(dpy);
  return 0;
}
