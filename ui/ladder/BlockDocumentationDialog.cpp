// SPDX-License-Identifier: GPL-3.0-or-later
#include "BlockDocumentationDialog.h"

#include "BlockDocumentation.h"
#include "WaveformPainter.h"

#include <QDialogButtonBox>
#include <QTextBrowser>
#include <QVBoxLayout>

namespace rs::ui {

namespace {

// Wide enough for a few seconds of events, narrow enough for a 1,024 px screen.
constexpr int kDiagramWidth = 760;

} // namespace

BlockDocumentationDialog::BlockDocumentationDialog(const blocks::LoadedLibrary& library,
                                                   const blocks::BlockDefinition& block,
                                                   QWidget* parent)
    : QDialog(parent), m_page(new QTextBrowser(this)) {
    setObjectName(QStringLiteral("blockDocumentationDialog"));
    setWindowTitle(
        tr("%1 — Block Documentation")
            .arg(QString::fromUtf8(block.name.data(), static_cast<qsizetype>(block.name.size()))));
    m_page->setObjectName(QStringLiteral("page"));
    const blockdoc::TimingExample example = blockdoc::runTimingExample(library, block);
    if (example.ran()) {
        std::vector<QString> labels;
        for (const std::string& label : example.labels)
            labels.push_back(QString::fromStdString(label));
        // DiagCode is read as the pattern the states table lists.
        auto valueText = [&example](int row, std::int64_t value) {
            return example.labels[static_cast<std::size_t>(row)] == "DiagCode"
                       ? QString::fromStdString(blockdoc::stateCode(static_cast<int>(value)))
                       : QString::number(value);
        };
        m_page->document()->addResource(
            QTextDocument::ImageResource, BlockDocumentation::timingDiagramUrl(),
            render::waveformImage(example.recording, labels, kDiagramWidth, palette(),
                                  devicePixelRatio(), valueText));
    }
    m_page->setHtml(BlockDocumentation::html(library, block, example));
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_page, 1);
    layout->addWidget(buttons);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    resize(kDiagramWidth + 80, 640);
}

void BlockDocumentationDialog::show(const blocks::LoadedLibrary& library,
                                    const blocks::BlockDefinition& block, QWidget* parent) {
    auto* dialog = new BlockDocumentationDialog(library, block, parent);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->QDialog::show();
}

} // namespace rs::ui
