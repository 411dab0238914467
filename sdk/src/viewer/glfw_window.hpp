// viewer/glfw_window.hpp — the live viewer's window (GLFW, OpenGL 3.3 core
// context current on the constructing thread, vsync on) and the virtual
// finger's mouse and keyboard controls.
//
// Controls (rates per second of holding, or per pixel of dragging):
//   left drag / arrow keys   slide the finger (0.02 mm/px, 2 mm/s)
//   wheel / W, S             press deeper, shallower (0.1 mm/notch, 1.5 mm/s)
//   Q, E                     twist (yaw, 20 deg/s)
//   right drag / I K, J L    pitch (vertical) and roll (horizontal) (0.2 deg/px, 20 deg/s)
//   space                    lift the finger off;   Z  re-zero;   Esc  close
#pragma once

#include <opencv2/core.hpp>
#include <string>

#include "viewer/virtual_finger.hpp"

struct GLFWwindow;

namespace onetip::viewer {

class ViewerWindow {
 public:
  // Throws std::runtime_error when GLFW or the 3.3 core context is unavailable.
  ViewerWindow(cv::Size size, const std::string& title);
  ~ViewerWindow();
  ViewerWindow(const ViewerWindow&) = delete;
  ViewerWindow& operator=(const ViewerWindow&) = delete;

  bool isOpen() const;
  cv::Size framebufferSize() const;
  // Shows the drawn frame and processes events.
  void present();
  // The finger controls gathered since the last call, over `dt` seconds.
  FingerControls takeControls(double dt);
  // True once per press of the re-zero key.
  bool takeRezero();

 private:
  GLFWwindow* window_ = nullptr;
};

// A one-line help for the window's title strip.
const char* virtualFingerHelp();

}  // namespace onetip::viewer
