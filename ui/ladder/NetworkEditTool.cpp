// SPDX-License-Identifier: GPL-3.0-or-later
#include "NetworkEditTool.h"

#include "LadderPage.h"

#include "document/ProjectDocument.h"

namespace rs::ui {

void NetworkEditTool::endEditSession() {
    m_page.rest();
}

} // namespace rs::ui
