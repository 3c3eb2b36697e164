#pragma once
// Qt for the batch command's plots: where no QApplication runs (`rollsim run`, `rollsim bench`), one is made on the
// offscreen platform for the scope of this object — no display needed nor used — and Qt's notes on its own set-up
// (no XDG_RUNTIME_DIR, fonts) are kept from the user, its critical and fatal messages passed on. Inside the window
// it does nothing.
#include <QtGlobal>
#include <memory>

class QApplication;

namespace rollsim::ui {

class OffscreenQt {
 public:
  OffscreenQt();
  ~OffscreenQt();
  OffscreenQt(const OffscreenQt&) = delete;
  OffscreenQt& operator=(const OffscreenQt&) = delete;

 private:
  std::unique_ptr<QApplication> own_;
  QtMessageHandler previous_ = nullptr;
};

}  // namespace rollsim::ui
