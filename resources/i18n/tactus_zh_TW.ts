<?xml version='1.0' encoding='utf-8'?>
<TS version="2.1" language="zh_TW">
<context>
    <name>QObject</name>
    <message>
        <location filename="../../widgets/editor_widget.cpp" line="18" />
        <source>typing</source>
        <translation>輸入</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="68" />
        <source>Cannot write %1: %2</source>
        <translation>無法寫入 %1：%2</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="72" />
        <source>Saving %1 failed: %2</source>
        <translation>儲存 %1 失敗：%2</translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="78" />
        <source>front</source>
        <translation>正面</translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="79" />
        <source>back, as read after turning the sheet</source>
        <translation>背面（翻頁後閱讀的方向）</translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="80" />
        <source>front and back</source>
        <translation>正面與背面</translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="82" />
        <source>Sheet %1 (%2) - pages %3 / %4</source>
        <translation>第 %1 張（%2）－ 第 %3 / %4 頁</translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="418" />
        <source>Tactus interpoint proof</source>
        <translation>Tactus 雙面點字校稿</translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="425" />
        <source>Cannot write %1</source>
        <translation>無法寫入 %1</translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="436" />
        <source>Cannot finish %1</source>
        <translation>無法完成 %1</translation>
    </message>
    <message>
        <location filename="../../widgets/accessibility.cpp" line="34" />
        <source>Divider between print and braille</source>
        <translation>明眼字與點字的分隔線</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="55" />
        <source>%1 s</source>
        <translation>%1 秒</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="57" />
        <source>%1 min %2 s</source>
        <translation>%1 分 %2 秒</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="58" />
        <source>%1 h %2 min</source>
        <translation>%1 小時 %2 分</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="30" />
        <source>waiting</source>
        <translation>等待中</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="31" />
        <source>embossing</source>
        <translation>列印中</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="32" />
        <source>paused</source>
        <translation>已暫停</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="33" />
        <source>done</source>
        <translation>已完成</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="34" />
        <source>stopped</source>
        <translation>已停止</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="35" />
        <source>cancelled</source>
        <translation>已取消</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <location filename="../../app/gui/main.cpp" line="44" />
        <source>Braille editor and embosser print manager: edit print and braille side by side, preview interpoint sheets, emboss.</source>
        <translation>點字編輯器與點字印表機管理：並排編輯明眼字與點字、預覽雙面點字、送印。</translation>
    </message>
    <message>
        <location filename="../../app/gui/main.cpp" line="50" />
        <source>Document to open (Markdown, text, DOCX, BRF, PEF).</source>
        <translation>要開啟的文件（Markdown、純文字、DOCX、BRF、PEF）。</translation>
    </message>
    <message>
        <location filename="../../app/gui/main.cpp" line="53" />
        <source>liblouis table, e.g. en-ueb-g2.ctb or zh-tw.ctb.</source>
        <translation>liblouis 點字表，例如 en-ueb-g2.ctb 或 zh-tw.ctb。</translation>
    </message>
    <message>
        <location filename="../../app/gui/main.cpp" line="56" />
        <source>Preview side: front, back or both.</source>
        <translation>預覽面：front、back 或 both。</translation>
    </message>
    <message>
        <location filename="../../app/gui/main.cpp" line="58" />
        <source>Sheet to preview.</source>
        <translation>要預覽的紙張。</translation>
    </message>
    <message>
        <location filename="../../app/gui/main.cpp" line="61" />
        <source>User interface language, e.g. zh_TW.</source>
        <translation>介面語言，例如 zh_TW。</translation>
    </message>
    <message>
        <location filename="../../app/gui/main.cpp" line="64" />
        <source>Save a picture of the window and quit.</source>
        <translation>儲存視窗畫面後結束。</translation>
    </message>
    <message>
        <location filename="../../app/gui/main.cpp" line="67" />
        <source>Panel to show: preview, motion, vibration, profile, printer.</source>
        <translation>要顯示的面板：preview、motion、vibration、profile、printer。</translation>
    </message>
    <message>
        <location filename="../../app/gui/main.cpp" line="70" />
        <source>Emboss the file on the last used embosser once it is open.</source>
        <translation>檔案開啟後，以上次使用的點字印表機列印。</translation>
    </message>
    <message>
        <location filename="../../app/gui/main.cpp" line="72" />
        <source>Do not offer to recover autosaved work.</source>
        <translation>不要詢問是否復原自動儲存的內容。</translation>
    </message>
</context>
<context>
    <name>tactus::gui::BraillePane</name>
    <message>
        <location filename="../../widgets/braille_pane.cpp" line="42" />
        <source>Braille</source>
        <translation>點字</translation>
    </message>
    <message>
        <location filename="../../widgets/braille_pane.cpp" line="44" />
        <source>The braille of each paragraph. Type with S D F J K L as dots 3 2 1 4 5 6; space, backspace and delete edit cells</source>
        <translation>每一段的點字。以 S D F J K L 輸入第 3 2 1 4 5 6 點；空白鍵、退格鍵與刪除鍵編輯點字方</translation>
    </message>
</context>
<context>
    <name>tactus::gui::EditorWidget</name>
    <message>
        <location filename="../../widgets/editor_widget.cpp" line="333" />
        <source>dots %1</source>
        <translation>點 %1</translation>
    </message>
</context>
<context>
    <name>tactus::gui::FindReplaceDialog</name>
    <message>
        <location filename="../../widgets/find_replace.cpp" line="21" />
        <source>Find and Replace</source>
        <translation>尋找與取代</translation>
    </message>
    <message>
        <location filename="../../widgets/find_replace.cpp" line="24" />
        <source>Find</source>
        <translation>尋找</translation>
    </message>
    <message>
        <location filename="../../widgets/find_replace.cpp" line="26" />
        <source>Replace with</source>
        <translation>取代為</translation>
    </message>
    <message>
        <location filename="../../widgets/find_replace.cpp" line="27" />
        <source>&amp;Match case</source>
        <translation>大小寫須相符(&amp;M)</translation>
    </message>
    <message>
        <location filename="../../widgets/find_replace.cpp" line="28" />
        <source>&amp;Whole words</source>
        <translation>全字拼寫須相符(&amp;W)</translation>
    </message>
    <message>
        <location filename="../../widgets/find_replace.cpp" line="30" />
        <source>Search result</source>
        <translation>搜尋結果</translation>
    </message>
    <message>
        <location filename="../../widgets/find_replace.cpp" line="32" />
        <source>F&amp;ind:</source>
        <translation>尋找(&amp;I)：</translation>
    </message>
    <message>
        <location filename="../../widgets/find_replace.cpp" line="33" />
        <source>Re&amp;place with:</source>
        <translation>取代為(&amp;P)：</translation>
    </message>
    <message>
        <location filename="../../widgets/find_replace.cpp" line="37" />
        <source>Find &amp;Next</source>
        <translation>找下一個(&amp;N)</translation>
    </message>
    <message>
        <location filename="../../widgets/find_replace.cpp" line="38" />
        <source>Find Pre&amp;vious</source>
        <translation>找上一個(&amp;V)</translation>
    </message>
    <message>
        <location filename="../../widgets/find_replace.cpp" line="39" />
        <source>&amp;Replace</source>
        <translation>取代(&amp;R)</translation>
    </message>
    <message>
        <location filename="../../widgets/find_replace.cpp" line="40" />
        <source>Replace &amp;All</source>
        <translation>全部取代(&amp;A)</translation>
    </message>
    <message>
        <location filename="../../widgets/find_replace.cpp" line="74" />
        <source>“%1” not found</source>
        <translation>找不到「%1」</translation>
    </message>
    <message>
        <location filename="../../widgets/find_replace.cpp" line="79" />
        <source>Found on line %1</source>
        <translation>在第 %1 行找到</translation>
    </message>
    <message numerus="yes">
        <location filename="../../widgets/find_replace.cpp" line="114" />
        <source>%n replaced</source>
        <translation><numerusform>已取代 %n 處</numerusform></translation>
    </message>
</context>
<context>
    <name>tactus::gui::MainWindow</name>
    <message>
        <location filename="../../widgets/main_window.cpp" line="84" />
        <location filename="../../widgets/main_window.cpp" line="487" />
        <location filename="../../widgets/main_window.cpp" line="612" />
        <source>Tactus</source>
        <translation>Tactus</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="94" />
        <source>Preview</source>
        <translation>預覽</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="101" />
        <source>Motion</source>
        <translation>運動</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="102" />
        <source>Vibration</source>
        <translation>振動</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="103" />
        <source>Printer profile</source>
        <translation>印表機設定檔</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="108" />
        <source>Printer</source>
        <translation>印表機</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="126" />
        <source>Braille</source>
        <translation>點字</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="128" />
        <source>Braille toolbar</source>
        <translation>點字工具列</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="129" />
        <source>&amp;Table:</source>
        <translation>點字表(&amp;T)：</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="136" />
        <source>Position</source>
        <translation>位置</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="139" />
        <source>Status</source>
        <translation>狀態</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="198" />
        <source>&amp;New</source>
        <translation>新增(&amp;N)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="201" />
        <source>&amp;Open or Import...</source>
        <translation>開啟或匯入(&amp;O)...</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="202" />
        <source>&amp;Save</source>
        <translation>儲存(&amp;S)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="203" />
        <source>Save &amp;As...</source>
        <translation>另存新檔(&amp;A)...</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="203" />
        <source>Ctrl+Shift+S</source>
        <translation>Ctrl+Shift+S</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="204" />
        <source>Export &amp;BRF...</source>
        <translation>匯出 BRF(&amp;B)...</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="204" />
        <source>Ctrl+E</source>
        <translation>Ctrl+E</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="206" />
        <source>Export &amp;PEF...</source>
        <translation>匯出 PEF(&amp;P)...</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="206" />
        <source>Ctrl+Shift+E</source>
        <translation>Ctrl+Shift+E</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="208" />
        <source>&amp;Quit</source>
        <translation>結束(&amp;Q)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="208" />
        <source>Ctrl+Q</source>
        <translation>Ctrl+Q</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="209" />
        <source>&amp;Undo</source>
        <translation>復原(&amp;U)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="212" />
        <source>&amp;Redo</source>
        <translation>重做(&amp;R)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="216" />
        <source>&amp;Find and Replace...</source>
        <translation>尋找與取代(&amp;F)...</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="222" />
        <source>Find &amp;Next</source>
        <translation>找下一個(&amp;N)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="224" />
        <source>Go to &amp;print text</source>
        <translation>移到明眼字(&amp;P)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="224" />
        <source>Ctrl+1</source>
        <translation>Ctrl+1</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="226" />
        <source>Go to &amp;braille</source>
        <translation>移到點字(&amp;B)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="226" />
        <source>Ctrl+2</source>
        <translation>Ctrl+2</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="228" />
        <source>Go to pre&amp;view</source>
        <translation>移到預覽(&amp;V)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="228" />
        <source>Ctrl+3</source>
        <translation>Ctrl+3</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="233" />
        <source>Choose braille &amp;table</source>
        <translation>選擇點字表(&amp;T)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="233" />
        <source>Ctrl+T</source>
        <translation>Ctrl+T</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="237" />
        <source>Go to &amp;motion</source>
        <translation>移到運動(&amp;M)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="237" />
        <source>Ctrl+4</source>
        <translation>Ctrl+4</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="241" />
        <source>Go to vibratio&amp;n</source>
        <translation>移到振動(&amp;N)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="241" />
        <source>Ctrl+5</source>
        <translation>Ctrl+5</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="245" />
        <source>Go to printer pro&amp;file</source>
        <translation>移到印表機設定檔(&amp;F)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="245" />
        <source>Ctrl+6</source>
        <translation>Ctrl+6</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="249" />
        <source>Go to p&amp;rinter</source>
        <translation>前往印表機(&amp;R)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="249" />
        <source>Ctrl+7</source>
        <translation>Ctrl+7</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="254" />
        <source>&amp;Emboss</source>
        <translation>列印點字(&amp;E)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="254" />
        <source>Ctrl+P</source>
        <translation>Ctrl+P</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="255" />
        <source>&amp;Keyboard Shortcuts</source>
        <translation>鍵盤快速鍵(&amp;K)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="255" />
        <source>Ctrl+F1</source>
        <translation>Ctrl+F1</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="257" />
        <source>&amp;About Tactus</source>
        <translation>關於 Tactus(&amp;A)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="257" />
        <source>Shift+F1</source>
        <translation>Shift+F1</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="260" />
        <source>Open the menu bar</source>
        <translation>開啟選單列</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="266" />
        <source>&amp;File</source>
        <translation>檔案(&amp;F)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="268" />
        <source>Open &amp;Recent</source>
        <translation>最近開啟(&amp;R)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="275" />
        <source>&amp;Edit</source>
        <translation>編輯(&amp;E)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="280" />
        <source>&amp;View</source>
        <translation>檢視(&amp;V)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="287" />
        <source>&amp;Help</source>
        <translation>說明(&amp;H)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="328" />
        <source>Translating with %1</source>
        <translation>正在以 %1 轉譯</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="333" />
        <source>Cannot use table %1: %2</source>
        <translation>無法使用點字表 %1：%2</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="337" />
        <location filename="../../widgets/main_window.cpp" line="450" />
        <source>Braille table: %1</source>
        <translation>點字表：%1</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="342" />
        <source>Warning: the table %1 does not suit all of this text (%2). Ctrl+T chooses another table.</source>
        <translation>警告：點字表 %1 不適用於這份文字的全部內容（%2）。按 Ctrl+T 選擇其他點字表。</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="359" />
        <source>Open or import</source>
        <translation>開啟或匯入</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="360" />
        <source>Documents (*.md *.markdown *.txt *.docx *.brf *.pef);;All files (*)</source>
        <translation>文件 (*.md *.markdown *.txt *.docx *.brf *.pef);;所有檔案 (*)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="366" />
        <source>Opening %1</source>
        <translation>正在開啟 %1</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="381" />
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="389" />
        <source>%1 percent</source>
        <translation>百分之 %1</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="416" />
        <source>Cancelled; the document is unchanged</source>
        <translation>已取消，文件未變更</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="421" />
        <source>Cannot open %1: %2</source>
        <translation>無法開啟 %1：%2</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="422" />
        <source>the document</source>
        <translation>文件</translation>
    </message>
    <message numerus="yes">
        <location filename="../../widgets/main_window.cpp" line="439" />
        <source>Opened %1: %n sheet(s)</source>
        <translation><numerusform>已開啟 %1：%n 張</numerusform></translation>
    </message>
    <message numerus="yes">
        <location filename="../../widgets/main_window.cpp" line="444" />
        <source>%n line(s) could not be translated; they are left out of the braille</source>
        <translation><numerusform>有 %n 行無法轉譯，未列入點字</numerusform></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="463" />
        <source>Sheet %1 of %2%3 | line %4 | cell %5 | print page %6</source>
        <translation>第 %1 張，共 %2 張%3 | 第 %4 行 | 第 %5 方 | 原書第 %6 頁</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="466" />
        <source>, back</source>
        <translation>，背面</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="466" />
        <source>, front</source>
        <translation>，正面</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="477" />
        <location filename="../../widgets/main_window.cpp" line="613" />
        <location filename="../../widgets/main_window.cpp" line="665" />
        <source>Untitled</source>
        <translation>未命名</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="498" />
        <source>Save as Markdown</source>
        <translation>另存為 Markdown</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="498" />
        <source>Markdown (*.md)</source>
        <translation>Markdown (*.md)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="520" />
        <source>Saved %1</source>
        <translation>已儲存 %1</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="525" />
        <location filename="../../widgets/main_window.cpp" line="563" />
        <source>untitled</source>
        <translation>未命名</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="526" />
        <source>PEF (*.pef)</source>
        <translation>PEF (*.pef)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="526" />
        <source>Braille ASCII (*.brf)</source>
        <translation>點字 ASCII (*.brf)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="528" />
        <source>Export</source>
        <translation>匯出</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="549" />
        <source>Cannot export %1: %2</source>
        <translation>無法匯出 %1：%2</translation>
    </message>
    <message numerus="yes">
        <location filename="../../widgets/main_window.cpp" line="558" />
        <source>Exported %1 (%n sheet(s))</source>
        <translation><numerusform>已匯出 %1（%n 張）</numerusform></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="565" />
        <source>Print preview to PDF</source>
        <translation>將預覽列印為 PDF</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="566" />
        <source>PDF (*.pdf)</source>
        <translation>PDF (*.pdf)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="577" />
        <source>Wrote proof %1</source>
        <translation>已寫出校稿 %1</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="612" />
        <source>Save the changes to %1?</source>
        <translation>要儲存對 %1 的變更嗎？</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="717" />
        <source>Cannot plan the job: %1</source>
        <translation>無法規劃工作：%1</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="770" />
        <source>Cannot read the autosaved copy %1: %2</source>
        <translation>無法讀取自動儲存的副本 %1：%2</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="785" />
        <source>Recovered</source>
        <translation>已復原</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="791" />
        <source>Recovered unsaved changes to %1</source>
        <translation>已復原 %1 未儲存的變更</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="797" />
        <source>an untitled document</source>
        <translation>未命名文件</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="799" />
        <source>Recover unsaved work</source>
        <translation>復原未儲存的內容</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="800" />
        <source>Tactus closed without saving %1 (autosaved %2). Recover it?</source>
        <translation>Tactus 關閉時 %1 尚未儲存（自動儲存於 %2）。要復原嗎？</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="819" />
        <source>Keyboard Shortcuts</source>
        <translation>鍵盤快速鍵</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="823" />
        <source>Shortcuts</source>
        <translation>快速鍵</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="825" />
        <source>Action</source>
        <translation>動作</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="825" />
        <source>Shortcut</source>
        <translation>快速鍵</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="854" />
        <source>Braille pane: dots 1 2 3 4 5 6 (chord, released together)</source>
        <translation>點字窗格：第 1 2 3 4 5 6 點（同時按下、一起放開）</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="854" />
        <source>F D S J K L</source>
        <translation>F D S J K L</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="855" />
        <source>Braille pane: blank cell / erase cell</source>
        <translation>點字窗格：空方 / 刪除點字方</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="855" />
        <source>Space / Backspace, Delete</source>
        <translation>空白鍵 / 退格鍵、刪除鍵</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="856" />
        <source>Preview: move between cells / lines</source>
        <translation>預覽：在點字方 / 行之間移動</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="856" />
        <source>Arrow keys</source>
        <translation>方向鍵</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="857" />
        <source>Preview: turn to the other side</source>
        <translation>預覽：翻到另一面</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="857" />
        <source>Space</source>
        <translation>空白鍵</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="858" />
        <source>Preview: previous / next sheet</source>
        <translation>預覽：上一張 / 下一張</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="858" />
        <source>PgUp / PgDown</source>
        <translation>PgUp / PgDown</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="859" />
        <source>Move between panes</source>
        <translation>在窗格之間移動</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="859" />
        <source>Tab / Shift+Tab</source>
        <translation>Tab / Shift+Tab</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="865" />
        <source>About Tactus</source>
        <translation>關於 Tactus</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="866" />
        <source>&lt;p&gt;&lt;b&gt;Tactus %1&lt;/b&gt;&lt;/p&gt;&lt;p&gt;Braille editor and embosser print manager.&lt;/p&gt;&lt;p&gt;Licensed under the GNU GPL, version 3 or later.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;Tactus %1&lt;/b&gt;&lt;/p&gt;&lt;p&gt;點字編輯器與點字印表機管理程式。&lt;/p&gt;&lt;p&gt;依 GNU GPL 第 3 版或更新版本授權。&lt;/p&gt;</translation>
    </message>
</context>
<context>
    <name>tactus::gui::MotionView</name>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="64" />
        <source>Sheet</source>
        <translation>紙張</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="66" />
        <source>Pass</source>
        <translation>行程</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="68" />
        <source>Quantity</source>
        <translation>物理量</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="69" />
        <source>Position (mm)</source>
        <translation>位置 (mm)</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="69" />
        <source>Velocity (mm/s)</source>
        <translation>速度 (mm/s)</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="69" />
        <source>Acceleration (mm/s²)</source>
        <translation>加速度 (mm/s²)</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="70" />
        <source>Jerk (mm/s³)</source>
        <translation>加加速度 (mm/s³)</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="71" />
        <source>Compare prof&amp;ile shapes</source>
        <translation>比較運動曲線(&amp;I)</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="75" />
        <source>&amp;Sheet:</source>
        <translation>紙張(&amp;S)：</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="76" />
        <source>P&amp;ass:</source>
        <translation>行程(&amp;A)：</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="77" />
        <source>Sho&amp;w:</source>
        <translation>顯示(&amp;W)：</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="84" />
        <source>Carriage motion chart</source>
        <translation>筆架運動圖</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="91" />
        <source>Time estimates</source>
        <translation>時間估計</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="97" />
        <source>Profile shapes on this pass</source>
        <translation>此行程的各種運動曲線</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="98" />
        <source>Profile shape</source>
        <translation>運動曲線</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="98" />
        <source>Pass time</source>
        <translation>行程時間</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="98" />
        <source>Versus lower bound</source>
        <translation>相對於下限</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="104" />
        <source>Strikes of this pass</source>
        <translation>此行程的擊點</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="105" />
        <location filename="../../widgets/motion_view.cpp" line="215" />
        <source>Time (ms)</source>
        <translation>時間 (ms)</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="105" />
        <source>Carriage (mm)</source>
        <translation>筆架 (mm)</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="105" />
        <source>Side</source>
        <translation>面</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="105" />
        <source>Residual (µm)</source>
        <translation>殘留振動 (µm)</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="148" />
        <source>No plan yet</source>
        <translation>尚未規劃</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="156" />
        <source>Sheet %1: %2 (lower bound %3, %4). Document, %5 sheets: %6 (lower bound %7, %8).</source>
        <translation>第 %1 張：%2（下限 %3，%4）。整份文件 %5 張：%6（下限 %7，%8）。</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="164" />
        <source>This sheet is blank.</source>
        <translation>這張是空白的。</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="168" />
        <source>Pass %1 (%2, %3 strikes): %4, lower bound %5.</source>
        <translation>行程 %1（%2，%3 個擊點）：%4，下限 %5。</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="170" />
        <location filename="../../widgets/motion_view.cpp" line="224" />
        <source>front</source>
        <translation>正面</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="170" />
        <location filename="../../widgets/motion_view.cpp" line="224" />
        <source>back</source>
        <translation>背面</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="177" />
        <location filename="../../widgets/motion_view.cpp" line="204" />
        <source>Planned (auto-tuned)</source>
        <translation>規劃（自動調校）</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="181" />
        <source>Strikes</source>
        <translation>擊點</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="194" />
        <source>Trapezoid</source>
        <translation>梯形</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="195" />
        <source>S-curve (smoothstep)</source>
        <translation>S 曲線（smoothstep）</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="196" />
        <source>Jerk-limited (7 segments)</source>
        <translation>限制加加速度（7 段）</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="217" />
        <source>Sheet %1, pass %2</source>
        <translation>第 %1 張，行程 %2</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="229" />
        <source>%1 against time for sheet %2, pass %3: %4 strikes over %5; from %6 to %7. The strike table lists the same data.</source>
        <translation>第 %2 張行程 %3 的%1對時間：%4 個擊點，歷時 %5；範圍 %6 到 %7。擊點表列出相同資料。</translation>
    </message>
</context>
<context>
    <name>tactus::gui::PreviewPanel</name>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="20" />
        <source>Preview scroll area</source>
        <translation>預覽捲動區</translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="36" />
        <source>Fr&amp;ont</source>
        <translation>正面(&amp;O)</translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="36" />
        <source>Ctrl+Alt+F</source>
        <translation>Ctrl+Alt+F</translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="37" />
        <source>Bac&amp;k</source>
        <translation>背面(&amp;K)</translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="37" />
        <source>Ctrl+Alt+B</source>
        <translation>Ctrl+Alt+B</translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="38" />
        <source>Front &amp;and back</source>
        <translation>正面與背面(&amp;A)</translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="38" />
        <source>Ctrl+Alt+A</source>
        <translation>Ctrl+Alt+A</translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="44" />
        <source>Pr&amp;evious sheet</source>
        <translation>上一張(&amp;E)</translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="44" />
        <source>Ctrl+PgUp</source>
        <translation>Ctrl+PgUp</translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="45" />
        <source>Ne&amp;xt sheet</source>
        <translation>下一張(&amp;X)</translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="45" />
        <source>Ctrl+PgDown</source>
        <translation>Ctrl+PgDown</translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="46" />
        <source>Zoom &amp;in</source>
        <translation>放大(&amp;I)</translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="47" />
        <source>Zoom o&amp;ut</source>
        <translation>縮小(&amp;U)</translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="48" />
        <source>&amp;High contrast</source>
        <translation>高對比(&amp;H)</translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="48" />
        <source>Ctrl+Alt+H</source>
        <translation>Ctrl+Alt+H</translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="50" />
        <source>Print preview to P&amp;DF...</source>
        <translation>將預覽列印為 PDF(&amp;D)...</translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="50" />
        <source>Ctrl+Alt+P</source>
        <translation>Ctrl+Alt+P</translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="62" />
        <source>Preview</source>
        <translation>預覽</translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="64" />
        <source>Preview controls</source>
        <translation>預覽控制</translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="70" />
        <source>Preview status</source>
        <translation>預覽狀態</translation>
    </message>
</context>
<context>
    <name>tactus::gui::PrintPane</name>
    <message>
        <location filename="../../widgets/braille_pane.cpp" line="165" />
        <source>Print text</source>
        <translation>明眼字</translation>
    </message>
    <message>
        <location filename="../../widgets/braille_pane.cpp" line="167" />
        <source>One paragraph per line: # for headings, - for list items, *italic*, **bold**</source>
        <translation>每行一段：# 為標題、- 為清單項目、*斜體*、**粗體**</translation>
    </message>
</context>
<context>
    <name>tactus::gui::PrinterPanel</name>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="62" />
        <source>Embosser</source>
        <translation>點字印表機</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="63" />
        <source>Serial ports with their USB descriptions, HID bridges, parallel ports, and the built-in simulator</source>
        <translation>序列埠（含 USB 說明）、HID 轉接器、平行埠，以及內建模擬器</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="64" />
        <source>&amp;Refresh</source>
        <translation>重新整理(&amp;R)</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="65" />
        <location filename="../../widgets/printer_panel.cpp" line="211" />
        <source>&amp;Connect</source>
        <translation>連線(&amp;C)</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="67" />
        <location filename="../../widgets/printer_panel.cpp" line="212" />
        <source>Not connected</source>
        <translation>未連線</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="69" />
        <source>Controller status</source>
        <translation>控制器狀態</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="74" />
        <source>Fault</source>
        <translation>故障</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="79" />
        <source>Job queue</source>
        <translation>工作佇列</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="80" />
        <source>Document</source>
        <translation>文件</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="80" />
        <source>State</source>
        <translation>狀態</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="80" />
        <source>Progress</source>
        <translation>進度</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="80" />
        <source>Sheet</source>
        <translation>紙張</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="86" />
        <source>&amp;Pause</source>
        <translation>暫停(&amp;P)</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="87" />
        <source>Res&amp;ume</source>
        <translation>繼續(&amp;U)</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="88" />
        <source>Ca&amp;ncel job</source>
        <translation>取消工作(&amp;N)</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="91" />
        <source>Braille page to resume from</source>
        <translation>從哪一個點字頁繼續</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="92" />
        <source>Resume from pa&amp;ge</source>
        <translation>從指定頁繼續(&amp;G)</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="96" />
        <source>Link log</source>
        <translation>連線紀錄</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="101" />
        <source>E&amp;mbosser:</source>
        <translation>點字印表機(&amp;M)：</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="120" />
        <source>Lin&amp;k log (for technicians):</source>
        <translation>連線紀錄（技術人員用）(&amp;K)：</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="156" />
        <source>Listing devices: %1</source>
        <translation>列出裝置：%1</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="186" />
        <source>Connecting to %1</source>
        <translation>正在連線到 %1</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="191" />
        <source>Cannot connect to %1: %2. Check that it is switched on and plugged in, then try again.</source>
        <translation>無法連線到 %1：%2。請確認電源已開啟且纜線已接好，然後再試一次。</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="197" />
        <source>Dis&amp;connect</source>
        <translation>中斷連線(&amp;C)</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="201" />
        <source>Connected to %1</source>
        <translation>已連線到 %1</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="209" />
        <source>Disconnected from %1</source>
        <translation>已與 %1 中斷連線</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="222" />
        <source>No answer from the embosser</source>
        <translation>點字印表機沒有回應</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="223" />
        <source>The embosser does not answer (%1). Check the cable and the power switch.</source>
        <translation>點字印表機沒有回應（%1）。請檢查纜線與電源開關。</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="226" />
        <source>Connected to %1: %2</source>
        <translation>已連線到 %1：%2</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="245" />
        <source>Progress of %1</source>
        <translation>%1 的進度</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="252" />
        <source>Queued %1 (job %2) from sheet %3</source>
        <translation>已將 %1 排入佇列（工作 %2），從第 %3 張開始</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="253" />
        <source>%1 added to the queue</source>
        <translation>%1 已加入佇列</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="296" />
        <source>Embossing %1: sheet %2 of %3, %4 percent</source>
        <translation>正在列印 %1：第 %2 張，共 %3 張，百分之 %4</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="299" />
        <source>%1: sheet %2 of %3</source>
        <translation>%1：第 %2 張，共 %3 張</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="300" />
        <source>%1: %2 percent, sheet %3 of %4</source>
        <translation>%1：百分之 %2，第 %3 張，共 %4 張</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="335" />
        <source>Embossing %1 from sheet %2</source>
        <translation>正在列印 %1，從第 %2 張開始</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="336" />
        <location filename="../../widgets/printer_panel.cpp" line="337" />
        <source>Embossing %1</source>
        <translation>正在列印 %1</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="350" />
        <source>Cannot plan the job: %1</source>
        <translation>無法規劃工作：%1</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="393" />
        <source>Link: %1 frames sent, %2 resent, %3 bytes, %4 NAKs, %5 timeouts, %6 reconnects, %7 restarts</source>
        <translation>連線：已傳送 %1 個訊框，重送 %2 個，%3 位元組，%4 次 NAK，%5 次逾時，%6 次重新連線，%7 次重新啟動</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="409" />
        <source>all %1 strikes checked against the plan</source>
        <translation>全部 %1 個擊點均已與規劃核對</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="410" />
        <source>%1 strikes embossed but %2 planned: the simulator disagrees with the plan</source>
        <translation>已列印 %1 個擊點，但規劃為 %2 個：模擬器與規劃不符</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="428" />
        <source>Embossed %1</source>
        <translation>已列印 %1</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="431" />
        <source>%1 cancelled; resume from sheet %2</source>
        <translation>%1 已取消；可從第 %2 張繼續</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="435" />
        <source>%1 stopped at sheet %2: %3. The queue is kept; fix the problem, then resume from sheet %2.</source>
        <translation>%1 停在第 %2 張：%3。佇列已保留；排除問題後，請從第 %2 張繼續。</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="456" />
        <source>Pause requested: the embosser stops at the end of the current move</source>
        <translation>已要求暫停：點字印表機會在目前動作結束時停止</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="457" />
        <source>Pausing</source>
        <translation>正在暫停</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="467" />
        <source>Resume requested</source>
        <translation>已要求繼續</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="468" />
        <source>Resuming</source>
        <translation>正在繼續</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="480" />
        <source>Cancel requested</source>
        <translation>已要求取消</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="495" />
        <source>Page %1 is not in %2 (it has %3 pages)</source>
        <translation>%2 沒有第 %1 頁（共 %3 頁）</translation>
    </message>
</context>
<context>
    <name>tactus::gui::ProfileEditor</name>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="30" />
        <source>Paper</source>
        <translation>紙張</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="31" />
        <source>Width</source>
        <translation>寬度</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="31" />
        <location filename="../../widgets/profile_editor.cpp" line="32" />
        <location filename="../../widgets/profile_editor.cpp" line="33" />
        <location filename="../../widgets/profile_editor.cpp" line="34" />
        <location filename="../../widgets/profile_editor.cpp" line="36" />
        <location filename="../../widgets/profile_editor.cpp" line="37" />
        <location filename="../../widgets/profile_editor.cpp" line="38" />
        <location filename="../../widgets/profile_editor.cpp" line="39" />
        <location filename="../../widgets/profile_editor.cpp" line="40" />
        <location filename="../../widgets/profile_editor.cpp" line="42" />
        <location filename="../../widgets/profile_editor.cpp" line="48" />
        <source>mm</source>
        <translation>mm</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="32" />
        <source>Height</source>
        <translation>高度</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="33" />
        <source>Left margin</source>
        <translation>左邊界</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="34" />
        <source>Top margin</source>
        <translation>上邊界</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="35" />
        <source>Braille geometry</source>
        <translation>點字幾何</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="36" />
        <source>Dot pitch</source>
        <translation>點距</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="37" />
        <source>Cell pitch</source>
        <translation>方距</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="38" />
        <source>Line pitch</source>
        <translation>行距</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="39" />
        <source>Back offset across</source>
        <translation>背面水平偏移</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="40" />
        <source>Back offset down</source>
        <translation>背面垂直偏移</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="41" />
        <source>Head and carriage</source>
        <translation>打點頭與筆架</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="42" />
        <source>Concave hammer offset</source>
        <translation>凹錘偏移</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="43" />
        <source>Hammer dwell</source>
        <translation>擊錘停留</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="43" />
        <source>s</source>
        <translation>秒</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="44" />
        <source>Carriage steps</source>
        <translation>筆架步數</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="44" />
        <source>steps/mm</source>
        <translation>步/mm</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="45" />
        <source>Carriage top speed</source>
        <translation>筆架最高速度</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="45" />
        <source>mm/s</source>
        <translation>mm/s</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="46" />
        <source>Carriage acceleration</source>
        <translation>筆架加速度</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="46" />
        <source>mm/s²</source>
        <translation>mm/s²</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="47" />
        <source>Carriage jerk</source>
        <translation>筆架加加速度</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="47" />
        <source>mm/s³</source>
        <translation>mm/s³</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="48" />
        <source>Carriage backlash</source>
        <translation>筆架背隙</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="49" />
        <source>Step timing tolerance</source>
        <translation>步進時間容許誤差</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="49" />
        <source>of a step interval</source>
        <translation>個步進間隔</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="50" />
        <source>Dynamics and vibration</source>
        <translation>動態與振動</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="51" />
        <source>Head mass</source>
        <translation>打點頭質量</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="51" />
        <source>kg</source>
        <translation>kg</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="52" />
        <source>Belt stiffness</source>
        <translation>皮帶剛性</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="52" />
        <source>N/m</source>
        <translation>N/m</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="53" />
        <source>Damping ratio</source>
        <translation>阻尼比</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="54" />
        <source>Position tolerance at the strike</source>
        <translation>擊點時的位置容許誤差</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="54" />
        <source>µm</source>
        <translation>µm</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="59" />
        <source>Profile fields</source>
        <translation>設定檔欄位</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="63" />
        <source>Profile check</source>
        <translation>設定檔檢查</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="64" />
        <source>&amp;Load profile...</source>
        <translation>載入設定檔(&amp;L)...</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="65" />
        <source>Save pr&amp;ofile...</source>
        <translation>儲存設定檔(&amp;O)...</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="66" />
        <source>&amp;Defaults</source>
        <translation>預設值(&amp;D)</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="68" />
        <source>Load printer profile</source>
        <translation>載入印表機設定檔</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="68" />
        <location filename="../../widgets/profile_editor.cpp" line="72" />
        <source>Profiles (*.json)</source>
        <translation>設定檔 (*.json)</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="72" />
        <source>Save printer profile</source>
        <translation>儲存印表機設定檔</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="95" />
        <source>%1 to %2 %3</source>
        <translation>%1 到 %2 %3</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="96" />
        <source>%1 in %2</source>
        <translation>%1（%2）</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="97" />
        <source>Range %1; profile field %2</source>
        <translation>範圍 %1；設定檔欄位 %2</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="135" />
        <source>%1 %2. The plan and preview keep the last valid profile.</source>
        <translation>%1 %2。規劃與預覽仍使用上一個有效的設定檔。</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="145" />
        <source>Profile is valid.</source>
        <translation>設定檔有效。</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="153" />
        <source>Cannot load %1: %2</source>
        <translation>無法載入 %1：%2</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="159" />
        <source>Loaded profile %1</source>
        <translation>已載入設定檔 %1</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="165" />
        <source>Cannot save %1: %2</source>
        <translation>無法儲存 %1：%2</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="168" />
        <source>Saved profile to %1</source>
        <translation>已將設定檔儲存到 %1</translation>
    </message>
</context>
<context>
    <name>tactus::gui::SheetPreview</name>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="125" />
        <source>Interpoint preview</source>
        <translation>雙面點字預覽</translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="126" />
        <source>Arrow keys move between cells; Page Up and Page Down change sheet</source>
        <translation>方向鍵在點字方之間移動；Page Up 與 Page Down 換頁</translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="226" />
        <source>Sheet %1 %2, line %3, cell %4</source>
        <translation>第 %1 張%2，第 %3 行，第 %4 方</translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="228" />
        <source>back</source>
        <translation>背面</translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="228" />
        <source>front</source>
        <translation>正面</translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="231" />
        <source>: no page</source>
        <translation>：沒有這一頁</translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="235" />
        <source>: blank</source>
        <translation>：空方</translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="237" />
        <source>dots %1</source>
        <translation>點 %1</translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="242" />
        <location filename="../../widgets/sheet_preview.cpp" line="250" />
        <source>, in the word “%1”</source>
        <translation>，在「%1」中</translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="256" />
        <location filename="../../widgets/sheet_preview.cpp" line="344" />
        <source>No document</source>
        <translation>沒有文件</translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="257" />
        <source>Sheet %1 of %2</source>
        <translation>第 %1 張，共 %2 張</translation>
    </message>
    <message numerus="yes">
        <location filename="../../widgets/sheet_preview.cpp" line="259" />
        <source>; %n front and back dots too close</source>
        <translation><numerusform>；有 %n 組正背面點距離過近</numerusform></translation>
    </message>
</context>
<context>
    <name>tactus::gui::TablePicker</name>
    <message>
        <location filename="../../widgets/table_picker.cpp" line="16" />
        <source>Unified English Braille</source>
        <translation>統一英文點字</translation>
    </message>
    <message>
        <location filename="../../widgets/table_picker.cpp" line="17" />
        <source>English Braille American Edition</source>
        <translation>美國版英文點字</translation>
    </message>
    <message>
        <location filename="../../widgets/table_picker.cpp" line="18" />
        <source>Taiwanese braille (bopomofo)</source>
        <translation>台灣國語點字（注音）</translation>
    </message>
    <message>
        <location filename="../../widgets/table_picker.cpp" line="19" />
        <source>current Chinese braille</source>
        <translation>現行中文點字</translation>
    </message>
    <message>
        <location filename="../../widgets/table_picker.cpp" line="20" />
        <source>two-cell Chinese braille</source>
        <translation>雙拼中文點字</translation>
    </message>
    <message>
        <location filename="../../widgets/table_picker.cpp" line="21" />
        <source>uncontracted</source>
        <translation>未縮寫</translation>
    </message>
    <message>
        <location filename="../../widgets/table_picker.cpp" line="22" />
        <source>partly contracted</source>
        <translation>部分縮寫</translation>
    </message>
    <message>
        <location filename="../../widgets/table_picker.cpp" line="23" />
        <source>contracted</source>
        <translation>縮寫</translation>
    </message>
    <message>
        <location filename="../../widgets/table_picker.cpp" line="24" />
        <source>grade %1</source>
        <translation>第 %1 級</translation>
    </message>
    <message>
        <location filename="../../widgets/table_picker.cpp" line="26" />
        <source>, </source>
        <comment>list separator</comment>
        <translation>，</translation>
    </message>
    <message>
        <location filename="../../widgets/table_picker.cpp" line="33" />
        <source>Braille table</source>
        <translation>點字表</translation>
    </message>
    <message>
        <location filename="../../widgets/table_picker.cpp" line="34" />
        <source>The language and braille code the print is translated with</source>
        <translation>用來轉譯明眼字的語言與點字系統</translation>
    </message>
</context>
<context>
    <name>tactus::gui::VibrationView</name>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="27" />
        <source>Step response against the targets</source>
        <translation>步階響應與目標比較</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="28" />
        <source>Quantity</source>
        <translation>物理量</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="28" />
        <source>Value</source>
        <translation>數值</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="28" />
        <source>Target</source>
        <translation>目標</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="28" />
        <source>Result</source>
        <translation>結果</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="36" />
        <source>Natural frequencies</source>
        <translation>自然頻率</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="40" />
        <source>Residual vibration at the strikes</source>
        <translation>擊點時的殘留振動</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="44" />
        <source>Residual vibration histogram</source>
        <translation>殘留振動直方圖</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="49" />
        <source>Frequency response chart</source>
        <translation>頻率響應圖</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="78" />
        <source>pass</source>
        <translation>通過</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="78" />
        <source>FAIL</source>
        <translation>未通過</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="82" />
        <source>Overshoot</source>
        <translation>超越量</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="82" />
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="82" />
        <source>&lt; %1 %</source>
        <translation>&lt; %1 %</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="84" />
        <source>Rise time (10-90 %)</source>
        <translation>上升時間（10-90 %）</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="84" />
        <location filename="../../widgets/vibration_view.cpp" line="87" />
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="85" />
        <location filename="../../widgets/vibration_view.cpp" line="88" />
        <source>&lt; %1 ms</source>
        <translation>&lt; %1 ms</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="86" />
        <source>Settling time (2 %)</source>
        <translation>安定時間（2 %）</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="87" />
        <source>never settles</source>
        <translation>無法安定</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="91" />
        <source>%1 model; natural frequencies %2 Hz; √(k/m) = %3 rad/s; damping ratio %4.</source>
        <translation>%1模型；自然頻率 %2 Hz；√(k/m) = %3 rad/s；阻尼比 %4。</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="92" />
        <source>Two-inertia</source>
        <translation>雙慣量</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="92" />
        <source>One-inertia</source>
        <translation>單慣量</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="100" />
        <source>Magnitude (dB)</source>
        <translation>增益 (dB)</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="102" />
        <source>Phase (degrees)</source>
        <translation>相位（度）</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="117" />
        <source>Frequency (Hz)</source>
        <translation>頻率 (Hz)</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="120" />
        <source>dB</source>
        <translation>dB</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="122" />
        <source>degrees</source>
        <translation>度</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="130" />
        <source>Head position versus command</source>
        <translation>打點頭位置對命令</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="131" />
        <source>Peak %1 dB at %2 Hz; %3 points from %4 to %5 Hz.</source>
        <translation>峰值 %1 dB 於 %2 Hz；%3 個點，從 %4 到 %5 Hz。</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="137" />
        <source>All targets met</source>
        <translation>全部達到目標</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="137" />
        <source>Some targets are not met</source>
        <translation>部分未達目標</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="147" />
        <source>No plan yet</source>
        <translation>尚未規劃</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="160" />
        <source>sheet %1, pass %2</source>
        <translation>第 %1 張行程 %2</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="166" />
        <source>Nominal machine</source>
        <translation>標稱機器</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="167" />
        <source>Worst case over the band</source>
        <translation>參數範圍內最差情況</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="186" />
        <source>Residual up to (µm)</source>
        <translation>殘留振動上限 (µm)</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="188" />
        <source>Strikes</source>
        <translation>擊點</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="195" />
        <source>Residual vibration per strike</source>
        <translation>每個擊點的殘留振動</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="197" />
        <source>%1 strikes on %2 planned sheets: worst case %3 µm at %4 (tolerance %5 µm) — %6.</source>
        <translation>已規劃 %2 張共 %1 個擊點：最差 %3 µm，位於%4（容許 %5 µm）— %6。</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="203" />
        <source>within tolerance</source>
        <translation>在容許範圍內</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="203" />
        <source>OVER TOLERANCE</source>
        <translation>超出容許範圍</translation>
    </message>
</context>
</TS>