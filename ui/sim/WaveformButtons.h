// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

class QToolButton;
class QWidget;

namespace rs::ui {

class WaveformView;

// The buttons every target's waveform panel has beside its input line.
struct WaveformButtons {
    QToolButton* remove;    // the chosen trace; enabled while one is chosen
    QToolButton* zoomIn;    // wired to the view
    QToolButton* zoomOut;   // wired to the view
    QToolButton* fit;       // wired to the view
    QToolButton* exportVcd; // the panel writes the file
};

WaveformButtons makeWaveformButtons(QWidget* owner, WaveformView* view);

} // namespace rs::ui
