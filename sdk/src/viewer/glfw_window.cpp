#include "viewer/glfw_window.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <stdexcept>
#include <string>

namespace onetip::viewer {

namespace {
// Input gathered by the callbacks between two takeControls() calls.
struct PendingInput {
  double wheel = 0;
  double last_x = 0, last_y = 0;
  bool have_last = false;
  double drag_x = 0, drag_y = 0;   // left button, pixels
  double tilt_x = 0, tilt_y = 0;   // right button, pixels
  bool lift = false, rezero = false;
};

// GLFW's description of its last error, or "" when it has none.
std::string lastGlfwError() {
  const char* description = nullptr;
  glfwGetError(&description);
  return description ? std::string(": ") + description : std::string();
}

PendingInput& pending(GLFWwindow* w) { return *static_cast<PendingInput*>(glfwGetWindowUserPointer(w)); }

void onScroll(GLFWwindow* w, double, double dy) { pending(w).wheel += dy; }
void onCursor(GLFWwindow* w, double x, double y) {
  PendingInput& p = pending(w);
  if (p.have_last) {
    if (glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS) p.drag_x += x - p.last_x, p.drag_y += y - p.last_y;
    if (glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS) p.tilt_x += x - p.last_x, p.tilt_y += y - p.last_y;
  }
  p.last_x = x, p.last_y = y, p.have_last = true;
}
void onKey(GLFWwindow* w, int key, int, int action, int) {
  if (action != GLFW_PRESS) return;
  if (key == GLFW_KEY_ESCAPE) glfwSetWindowShouldClose(w, GLFW_TRUE);
  if (key == GLFW_KEY_SPACE) pending(w).lift = true;
  if (key == GLFW_KEY_Z) pending(w).rezero = true;
}
}  // namespace

ViewerWindow::ViewerWindow(cv::Size size, const std::string& title) {
  if (!glfwInit()) throw std::runtime_error("viewer window: GLFW cannot initialise (no display?)" + lastGlfwError());
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_RESIZABLE, GLFW_FALSE);
  window_ = glfwCreateWindow(size.width, size.height, title.c_str(), nullptr, nullptr);
  if (!window_) {
    const std::string why = lastGlfwError();
    glfwTerminate();
    throw std::runtime_error("viewer window: cannot create an OpenGL 3.3 core window" + why);
  }
  glfwSetWindowUserPointer(window_, new PendingInput);
  glfwSetScrollCallback(window_, onScroll);
  glfwSetCursorPosCallback(window_, onCursor);
  glfwSetKeyCallback(window_, onKey);
  glfwMakeContextCurrent(window_);
  glfwSwapInterval(1);
}

ViewerWindow::~ViewerWindow() {
  delete &pending(window_);
  glfwDestroyWindow(window_);
  glfwTerminate();
}

bool ViewerWindow::isOpen() const { return !glfwWindowShouldClose(window_); }

cv::Size ViewerWindow::framebufferSize() const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  return {w, h};
}

void ViewerWindow::present() {
  glfwSwapBuffers(window_);
  glfwPollEvents();
}

FingerControls ViewerWindow::takeControls(double dt) {
  PendingInput& p = pending(window_);
  auto held = [&](int plus, int minus) {
    return (glfwGetKey(window_, plus) == GLFW_PRESS ? 1.0 : 0.0) - (glfwGetKey(window_, minus) == GLFW_PRESS ? 1.0 : 0.0);
  };
  FingerControls c;
  c.slide_x = 0.02 * p.drag_x + 2.0 * dt * held(GLFW_KEY_RIGHT, GLFW_KEY_LEFT);
  c.slide_y = 0.02 * p.drag_y + 2.0 * dt * held(GLFW_KEY_DOWN, GLFW_KEY_UP);
  c.press = 0.1 * p.wheel + 1.5 * dt * held(GLFW_KEY_W, GLFW_KEY_S);
  c.twist = 20.0 * dt * held(GLFW_KEY_E, GLFW_KEY_Q);
  c.pitch = 0.2 * p.tilt_y + 20.0 * dt * held(GLFW_KEY_K, GLFW_KEY_I);
  c.roll = 0.2 * p.tilt_x + 20.0 * dt * held(GLFW_KEY_L, GLFW_KEY_J);
  c.lift = p.lift;
  const PendingInput kept{0, p.last_x, p.last_y, p.have_last, 0, 0, 0, 0, false, p.rezero};
  p = kept;
  return c;
}

bool ViewerWindow::takeRezero() {
  PendingInput& p = pending(window_);
  const bool r = p.rezero;
  p.rezero = false;
  return r;
}

const char* virtualFingerHelp() {
  return "finger: L-drag/arrows slide  wheel/W,S press  Q,E twist  R-drag/IJKL tilt  space lift  Z re-zero";
}

}  // namespace onetip::viewer
