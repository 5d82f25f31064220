#pragma once

#include <QAbstractScrollArea>

#include <cstdint>

namespace rs::ui {

class WaveformRecorder;

// Draws what the recorder holds over virtual time: bits as 0/1 traces,
// numbers as bands with their value. Time runs left to right; the scroll bar
// moves along it, Ctrl+wheel or zoomIn()/zoomOut() change the scale, and the
// view follows the newest sample while it is scrolled to the end.
class WaveformView : public QAbstractScrollArea {
    Q_OBJECT
public:
    static constexpr int kNameWidth = 150;
    static constexpr int kRulerHeight = 22;
    static constexpr int kRowHeight = 28;

    explicit WaveformView(const WaveformRecorder* recorder, QWidget* parent = nullptr);

    // The recording grew or changed: new extent, and the end shown when following.
    void recordingChanged();

    double msPerPixel() const { return m_msPerPixel; }
    void setMsPerPixel(double msPerPixel);
    void zoomIn();
    void zoomOut();
    void zoomToFit();
    // The time at the left edge of the plot.
    std::int64_t firstVisibleMs() const;
    // Which trace is chosen (for removal), -1 when none.
    int selectedRow() const { return m_selected; }

    QSize sizeHint() const override;

signals:
    void selectionChanged(int row);

protected:
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void scrollContentsBy(int dx, int dy) override;

private:
    void updateScrollBars();
    int plotWidth() const;
    double xOf(std::int64_t timeMs) const;
    void paintRuler(QPainter& painter, int width);

    const WaveformRecorder* m_recorder;
    double m_msPerPixel = 1.0;
    bool m_follow = true;
    int m_selected = -1;
};

} // namespace rs::ui
