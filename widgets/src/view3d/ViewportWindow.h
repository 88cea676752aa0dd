#pragma once
/** @file
 * @brief Internal to ViewportWidget: the native OpenGL 3.3 core window the 3D view draws into, shown in
 *        the widget through QWidget::createWindowContainer. It draws straight into its own default
 *        framebuffer and swaps, so no QOpenGLWidget composition into the top-level window takes place
 *        (on llvmpipe that composition costs tens of ms a frame).
 *
 * It only draws: it is transparent for input (the widget beneath receives the mouse, the wheel and the
 * keys, and keeps the focus), and calls back its owner for the GL work (initialize, resize, paint).
 * Sizes: width()/height() logical pixels; deviceSize() device pixels. GUI thread only.
 */
#include <QImage>
#include <QOpenGLWindow>
#include <QSize>

#include <functional>

namespace stylos::widgets {

class ViewportWindow : public QOpenGLWindow {
    Q_OBJECT

public:
    struct Callbacks {
        std::function<void()> initialize;     ///< the context is new and current
        std::function<void()> resize;         ///< the window's size changed (current)
        std::function<void(unsigned)> paint;  ///< draw the frame into this framebuffer (current)
    };

    explicit ViewportWindow(Callbacks callbacks);

    /** @brief Schedules a frame (one posted event, coalesced), painted and swapped in it. */
    void scheduleRender();
    /** @brief Paints and swaps a frame now, if the window is exposed (with @p finish, then waits for the
     *         GL to finish the swap too); true when it did. */
    bool renderNow(bool finish = false);
    /** @brief Paints a frame into the back buffer and reads it (not swapped); null when not valid. */
    QImage grabFrame();
    QSize deviceSize() const;

protected:
    void initializeGL() override;
    void resizeGL(int width, int height) override;
    void paintGL() override;
    bool event(QEvent* event) override;

private:
    Callbacks m_callbacks;
    bool m_posted = false;
};

} // namespace stylos::widgets
