// SPDX-License-Identifier: GPL-3.0-or-later
#include "sim/WaveformButtons.h"

#include "sim/WaveformView.h"

#include <QCoreApplication>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QToolButton>
#include <QVBoxLayout>

namespace rs::ui {

WaveformButtons makeWaveformButtons(QWidget* owner, WaveformView* view) {
    const auto button = [owner](const QString& text, const QString& tip) {
        auto* created = new QToolButton(owner);
        created->setText(text);
        created->setToolTip(tip);
        return created;
    };
    WaveformButtons buttons{
        button(QCoreApplication::translate("rs::ui::WaveformPanel", "Remove"),
               QCoreApplication::translate("rs::ui::WaveformPanel",
                                           "Stop plotting the chosen variable")),
        button(QStringLiteral("+"),
               QCoreApplication::translate("rs::ui::WaveformPanel",
                                           "Zoom in: show less time (Ctrl+wheel)")),
        button(QStringLiteral("\u2212"),
               QCoreApplication::translate("rs::ui::WaveformPanel",
                                           "Zoom out: show more time (Ctrl+wheel)")),
        button(QCoreApplication::translate("rs::ui::WaveformPanel", "Fit"),
               QCoreApplication::translate("rs::ui::WaveformPanel", "Show the whole recording")),
        button(
            QCoreApplication::translate("rs::ui::WaveformPanel", "Export VCD..."),
            QCoreApplication::translate("rs::ui::WaveformPanel",
                                        "Write the recording as a Value Change Dump, for GTKWave")),
    };
    buttons.remove->setEnabled(false);
    buttons.exportVcd->setObjectName(QStringLiteral("exportVcdButton"));
    QObject::connect(buttons.zoomIn, &QToolButton::clicked, view, &WaveformView::zoomIn);
    QObject::connect(buttons.zoomOut, &QToolButton::clicked, view, &WaveformView::zoomOut);
    QObject::connect(buttons.fit, &QToolButton::clicked, view, &WaveformView::zoomToFit);
    QObject::connect(view, &WaveformView::selectionChanged, buttons.remove,
                     [remove = buttons.remove](int row) { remove->setEnabled(row >= 0); });
    return buttons;
}

void layOutWaveformPanel(QWidget* panel, QLineEdit* input, const QList<QToolButton*>& buttons,
                         QLabel* message, WaveformView* view,
                         std::function<QString(const QString&)> add) {
    auto* top = new QHBoxLayout;
    top->addWidget(input, 1);
    for (QToolButton* button : buttons)
        top->addWidget(button);
    auto* layout = new QVBoxLayout(panel);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addLayout(top);
    layout->addWidget(message);
    layout->addWidget(view, 1);
    QObject::connect(input, &QLineEdit::returnPressed, panel,
                     [input, message, add = std::move(add)] {
                         const QString error = add(input->text());
                         message->setText(error);
                         message->setVisible(!error.isEmpty());
                         if (error.isEmpty())
                             input->clear();
                     });
}

} // namespace rs::ui
