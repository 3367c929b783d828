<?xml version='1.0' encoding='utf-8'?>
<!DOCTYPE TS>
<TS version="2.1" language="nb_NO">
<context>
    <name>QObject</name>
    <message>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="27" />
        <source>%1 %2 × %3</source>
        <translation>%1 %2 × %3</translation>
    </message>
</context>
<context>
    <name>auv::ui::CraneWeighingPage</name>
    <message>
        <location filename="../../ui/pages/crane_weighing_page.cpp" line="34" />
        <source>Weighing with crane scales</source>
        <translation>Veiing med kranvekter</translation>
    </message>
    <message>
        <location filename="../../ui/pages/crane_weighing_page.cpp" line="35" />
        <source>Hang the vehicle from two ropes, fore and aft, with a crane scale at each rope end, and read the hook scale for the total.</source>
        <translation>Heng fartøyet i to stropper, forut og akter, med en kranvekt i hver stroppende, og les av vekten i kroken for totalen.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/crane_weighing_page.cpp" line="37" />
        <source>Fore / &amp;starboard:</source>
        <translation>Forut / &amp;styrbord:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/crane_weighing_page.cpp" line="37" />
        <source>Fore / &amp;port:</source>
        <translation>Forut / &amp;babord:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/crane_weighing_page.cpp" line="37" />
        <source>Aft / s&amp;tarboard:</source>
        <translation>Akter / s&amp;tyrbord:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/crane_weighing_page.cpp" line="38" />
        <source>Aft / p&amp;ort:</source>
        <translation>Akter / b&amp;abord:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/crane_weighing_page.cpp" line="40" />
        <source>Scale readings</source>
        <translation>Vektavlesninger</translation>
    </message>
    <message>
        <location filename="../../ui/pages/crane_weighing_page.cpp" line="45" />
        <source>Reading of the crane scale at this rope end, in kg, with the vehicle hanging still.</source>
        <translation>Avlesning av kranvekten i denne stroppenden, i kg, med fartøyet hengende i ro.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/crane_weighing_page.cpp" line="48" />
        <source>Reading of the scale on the crane hook (the whole vehicle).</source>
        <translation>Avlesning av vekten i krankroken (hele fartøyet).</translation>
    </message>
    <message>
        <location filename="../../ui/pages/crane_weighing_page.cpp" line="49" />
        <source>&amp;Hook (total):</source>
        <translation>&amp;Krok (total):</translation>
    </message>
    <message>
        <location filename="../../ui/pages/crane_weighing_page.cpp" line="54" />
        <source>Rope positions</source>
        <translation>Stroppeposisjoner</translation>
    </message>
    <message>
        <location filename="../../ui/pages/crane_weighing_page.cpp" line="57" />
        <source>x of the fore rope from the vehicle origin, forward positive (measure along the hull).</source>
        <translation>x for fremre stropp fra fartøyets origo, positiv forover (mål langs skroget).</translation>
    </message>
    <message>
        <location filename="../../ui/pages/crane_weighing_page.cpp" line="58" />
        <source>x of the aft rope from the vehicle origin, forward positive.</source>
        <translation>x for aktre stropp fra fartøyets origo, positiv forover.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/crane_weighing_page.cpp" line="59" />
        <source>Half the lateral distance between the two ends of one rope.</source>
        <translation>Halve sideavstanden mellom de to endene av en stropp.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/crane_weighing_page.cpp" line="60" />
        <source>&amp;Fore rope x:</source>
        <translation>&amp;Fremre stropp x:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/crane_weighing_page.cpp" line="61" />
        <source>&amp;Aft rope x:</source>
        <translation>&amp;Aktre stropp x:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/crane_weighing_page.cpp" line="62" />
        <source>Rope end &amp;y (±):</source>
        <translation>Stroppende &amp;y (±):</translation>
    </message>
    <message>
        <location filename="../../ui/pages/crane_weighing_page.cpp" line="64" />
        <source>Adjustment weight installed now</source>
        <translation>Trimvekt montert nå</translation>
    </message>
    <message>
        <location filename="../../ui/pages/crane_weighing_page.cpp" line="68" />
        <source>Kit pieces already in this point, in kg.</source>
        <translation>Vektlodd som allerede sitter i dette punktet, i kg.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/crane_weighing_page.cpp" line="95" />
        <source>Kit pieces already in '%1', in kg.</source>
        <translation>Vektlodd som allerede sitter i «%1», i kg.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/crane_weighing_page.cpp" line="112" />
        <source>Parts add up to %1 kg (%2 kg against the hook)</source>
        <translation>Delene summerer til %1 kg (%2 kg mot kroken)</translation>
    </message>
    <message>
        <location filename="../../ui/pages/crane_weighing_page.cpp" line="117" />
        <source>: more than %1 kg, check the readings</source>
        <translation>: mer enn %1 kg, kontroller avlesningene</translation>
    </message>
    <message>
        <location filename="../../ui/pages/crane_weighing_page.cpp" line="120" />
        <source>: re-read the scales</source>
        <translation>: les av vektene på nytt</translation>
    </message>
</context>
<context>
    <name>auv::ui::DeviationPlotsPage</name>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="29" />
        <source>Depth, pitch and roll as flown</source>
        <translation>Dybde, stamp og rull slik det ble kjørt</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="30" />
        <source>Measured against commanded. Wheel or +/- zooms in time, drag or the arrow keys move, double-click shows the whole log; the three charts move together.</source>
        <translation>Målt mot kommandert. Hjulet eller +/- zoomer i tid, dra eller piltastene flytter, dobbeltklikk viser hele loggen; de tre diagrammene følger hverandre.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="32" />
        <source>Depth [m]</source>
        <translation>Dybde [m]</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="32" />
        <source>Pitch [°]</source>
        <translation>Stamp [°]</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="32" />
        <source>Roll [°]</source>
        <translation>Rull [°]</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="59" />
        <source>measured</source>
        <translation>målt</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="59" />
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="121" />
        <source>commanded</source>
        <translation>kommandert</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="73" />
        <source>time since start [min]</source>
        <translation>tid siden start [min]</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="88" />
        <source>&amp;Whole log</source>
        <translation>&amp;Hele loggen</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="90" />
        <source>Show the whole log in all three charts.</source>
        <translation>Vis hele loggen i alle tre diagrammene.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="124" />
        <source>not in this log: %1</source>
        <translation>ikke i denne loggen: %1</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="140" />
        <source>%1: %2 samples in the three charts over %3 min.</source>
        <translation>%1: %2 målepunkter i de tre diagrammene over %3 min.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="239" />
        <source>Not saved: %1</source>
        <translation>Ikke lagret: %1</translation>
    </message>
</context>
<context>
    <name>auv::ui::FirstMissionResultPage</name>
    <message>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="28" />
        <source>add</source>
        <translation>legg til</translation>
    </message>
    <message>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="28" />
        <source>remove</source>
        <translation>fjern</translation>
    </message>
    <message>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="32" />
        <source>no change</source>
        <translation>ingen endring</translation>
    </message>
    <message>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="50" />
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="90" />
        <source>Ballast change before the first mission</source>
        <translation>Ballastendring før første oppdrag</translation>
    </message>
    <message>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="70" />
        <source>Point</source>
        <translation>Punkt</translation>
    </message>
    <message>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="70" />
        <source>Change</source>
        <translation>Endring</translation>
    </message>
    <message>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="70" />
        <source>Pieces</source>
        <translation>Lodd</translation>
    </message>
    <message>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="90" />
        <source>Ballast change after the tank weighing</source>
        <translation>Ballastendring etter tankveiingen</translation>
    </message>
    <message>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="97" />
        <source>Cannot compute: %1</source>
        <translation>Kan ikke beregne: %1</translation>
    </message>
    <message>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="106" />
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="139" />
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="143" />
        <source>%1 g</source>
        <translation>%1 g</translation>
    </message>
    <message>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="107" />
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="140" />
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="144" />
        <source>%1 kg</source>
        <translation>%1 kg</translation>
    </message>
    <message>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="108" />
        <source>neutral</source>
        <translation>nøytral</translation>
    </message>
    <message>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="109" />
        <source>too light</source>
        <translation>for lett</translation>
    </message>
    <message>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="110" />
        <source>too heavy</source>
        <translation>for tung</translation>
    </message>
    <message>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="111" />
        <source>Weighed %1 kg; buoyancy %2 kg in %3 kg/m³ water → net buoyancy %4 (%5). CG − CB: x %6 mm, y %7 mm; static pitch %8°, roll %9°.</source>
        <translation>Veid %1 kg; oppdrift %2 kg i %3 kg/m³ vann → netto oppdrift %4 (%5). CG − CB: x %6 mm, y %7 mm; statisk stamp %8°, rull %9°.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="137" />
        <source>After the change: net buoyancy %1 %2 (band %3..%4), pitch %5° %6 (±%7), roll %8° %9 (±%10).</source>
        <translation>Etter endringen: netto oppdrift %1 %2 (bånd %3..%4), stamp %5° %6 (±%7), rull %8° %9 (±%10).</translation>
    </message>
    <message>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="152" />
        <source>⚠ %1</source>
        <translation>⚠ %1</translation>
    </message>
    <message>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="166" />
        <source>Not saved: %1</source>
        <translation>Ikke lagret: %1</translation>
    </message>
</context>
<context>
    <name>auv::ui::HelpDialog</name>
    <message>
        <location filename="../../ui/widgets/help_dialog.cpp" line="14" />
        <source>auvballast - technician's guide</source>
        <translation>auvballast - veiledning for teknikere</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/help_dialog.cpp" line="24" />
        <source>The guide was not found at %1.</source>
        <translation>Fant ikke veiledningen i %1.</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/help_dialog.cpp" line="27" />
        <source>&amp;Close</source>
        <translation>&amp;Lukk</translation>
    </message>
</context>
<context>
    <name>auv::ui::LinkedChartView</name>
    <message>
        <location filename="../../ui/widgets/linked_chart_view.cpp" line="16" />
        <source>Wheel or +/-: zoom in time. Drag or arrow keys: move in time. Double-click or Home: whole log. All three charts follow.</source>
        <translation>Hjul eller +/-: zoom i tid. Dra eller piltaster: flytt i tid. Dobbeltklikk eller Home: hele loggen. Alle tre diagrammene følger.</translation>
    </message>
</context>
<context>
    <name>auv::ui::LogImportPage</name>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="28" />
        <source>cells that are not numbers</source>
        <translation>celler som ikke er tall</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="29" />
        <source>rows with the wrong number of cells</source>
        <translation>rader med feil antall celler</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="30" />
        <source>rows without a time</source>
        <translation>rader uten tid</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="31" />
        <source>rows going back in time</source>
        <translation>rader som går tilbake i tid</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="32" />
        <source>rows repeating the previous time (merged)</source>
        <translation>rader med samme tid som forrige (slått sammen)</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="33" />
        <source>repeated times with different values</source>
        <translation>gjentatte tider med ulike verdier</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="34" />
        <source>fill values or huge numbers (blanked)</source>
        <translation>fyllverdier eller enorme tall (tømt)</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="35" />
        <source>a last line cut short</source>
        <translation>en siste linje som er kuttet</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="36" />
        <source>overlong lines</source>
        <translation>for lange linjer</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="37" />
        <source>comment lines among the rows</source>
        <translation>kommentarlinjer blant radene</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="38" />
        <source>columns without a unit (unit assumed)</source>
        <translation>kolonner uten enhet (enhet antatt)</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="39" />
        <source>columns without a name (ignored)</source>
        <translation>kolonner uten navn (ignorert)</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="40" />
        <source>repeated column names (renamed)</source>
        <translation>gjentatte kolonnenavn (omdøpt)</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="41" />
        <source>no line end after the last row</source>
        <translation>ingen linjeslutt etter siste rad</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="42" />
        <source>long gaps in time</source>
        <translation>lange opphold i tid</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="43" />
        <source>times without a zone (UTC assumed)</source>
        <translation>tider uten sone (UTC antatt)</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="61" />
        <source>Import the mission log</source>
        <translation>Importer oppdragsloggen</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="62" />
        <source>Choose the log of the mission, or drop the file onto this page. The format is recognised from the content, not the file name.</source>
        <translation>Velg loggen fra oppdraget, eller slipp filen på denne siden. Formatet gjenkjennes fra innholdet, ikke filnavnet.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="67" />
        <source>The mission log file: the vehicle's log converted to the mission-log CSV.</source>
        <translation>Oppdragsloggfilen: fartøyets logg konvertert til oppdragslogg-CSV.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="69" />
        <source>&amp;Browse…</source>
        <translation>&amp;Bla gjennom…</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="69" />
        <source>Choose the log file.</source>
        <translation>Velg loggfilen.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="70" />
        <source>&amp;Import</source>
        <translation>&amp;Importer</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="70" />
        <source>Read the file named on the left.</source>
        <translation>Les filen som er angitt til venstre.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="76" />
        <source>How much of the file has been read.</source>
        <translation>Hvor mye av filen som er lest.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="77" />
        <source>&amp;Cancel import</source>
        <translation>&amp;Avbryt import</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="77" />
        <source>Stop reading; nothing of this file is kept.</source>
        <translation>Stopp lesingen; ingenting fra denne filen beholdes.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="79" />
        <source>↓ Drop a log file here ↓</source>
        <translation>↓ Slipp en loggfil her ↓</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="94" />
        <source>The first problems of each kind, with the line and what to do.</source>
        <translation>De første problemene av hver type, med linje og hva du bør gjøre.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="97" />
        <source>Log file:</source>
        <translation>Loggfil:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="117" />
        <source>Cancelling…</source>
        <translation>Avbryter…</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="136" />
        <source>Mission log</source>
        <translation>Oppdragslogg</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="137" />
        <source>Mission logs (*.csv *.txt *.log);;All files (*)</source>
        <translation>Oppdragslogger (*.csv *.txt *.log);;Alle filer (*)</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="165" />
        <source>Reading %1…</source>
        <translation>Leser %1…</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="184" />
        <source>Read completely.</source>
        <translation>Ferdig lest.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="188" />
        <source>Import cancelled at %1 %; nothing of this file was kept.</source>
        <translation>Importen ble avbrutt ved %1 %; ingenting fra denne filen ble beholdt.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="192" />
        <source>Cannot read this file: %1</source>
        <translation>Kan ikke lese denne filen: %1</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="214" />
        <source>%1 × %2</source>
        <translation>%1 × %2</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="217" />
        <source>&lt;b&gt;%1&lt;/b&gt; (%2): &lt;b&gt;%3 rows&lt;/b&gt; × &lt;b&gt;%4 channels&lt;/b&gt; over %5 h. Skipped %6 rows, merged %7, blanked %8 cells.&lt;br&gt;Plotted channels: %9&lt;br&gt;%10</source>
        <translation>&lt;b&gt;%1&lt;/b&gt; (%2): &lt;b&gt;%3 rader&lt;/b&gt; × &lt;b&gt;%4 kanaler&lt;/b&gt; over %5 t. Hoppet over %6 rader, slo sammen %7, tømte %8 celler.&lt;br&gt;Plottede kanaler: %9&lt;br&gt;%10</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="227" />
        <source>Nothing was skipped or changed.</source>
        <translation>Ingenting ble hoppet over eller endret.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="227" />
        <source>Why: %1.</source>
        <translation>Hvorfor: %1.</translation>
    </message>
</context>
<context>
    <name>auv::ui::OperatorWizard</name>
    <message>
        <location filename="../../ui/wizard/operator_wizard.cpp" line="28" />
        <source>auvballast - ballast wizard</source>
        <translation>auvballast - ballastveiviser</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/operator_wizard.cpp" line="33" />
        <source>&lt; &amp;Back</source>
        <translation>&lt; &amp;Tilbake</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/operator_wizard.cpp" line="34" />
        <source>&amp;Next &gt;</source>
        <translation>&amp;Neste &gt;</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/operator_wizard.cpp" line="35" />
        <source>&amp;Finish</source>
        <translation>&amp;Fullfør</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/operator_wizard.cpp" line="36" />
        <source>Cancel</source>
        <translation>Avbryt</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/operator_wizard.cpp" line="37" />
        <source>&amp;Help</source>
        <translation>&amp;Hjelp</translation>
    </message>
</context>
<context>
    <name>auv::ui::RollTestPage</name>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="25" />
        <source>Bow, port:</source>
        <translation>Baug, babord:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="25" />
        <source>Bow, starboard:</source>
        <translation>Baug, styrbord:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="26" />
        <source>Aft, upper:</source>
        <translation>Akter, øvre:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="26" />
        <source>Aft, lower:</source>
        <translation>Akter, nedre:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="40" />
        <source>Slocum roll test</source>
        <translation>Rulltest av Slocum</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="41" />
        <source>Wings off, glider hanging free from the nose hook and tail loop. Read m_roll with nothing hung, then with each known mass hung on a wing rail.</source>
        <translation>Vingene av, glideren henger fritt i nesekroken og halestroppen. Les av m_roll uten noe hengt på, deretter med hver kjente masse hengt på en vingeskinne.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="44" />
        <source>&amp;Bottles set after the tank step</source>
        <translation>&amp;Flasker satt etter tanktrinnet</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="46" />
        <source>Tick when you have changed the bottles as the tank step said: the roll test then refers to these contents.</source>
        <translation>Kryss av når du har endret flaskene slik tanktrinnet sa: rulltesten gjelder da dette innholdet.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="48" />
        <source>Bottles now</source>
        <translation>Flasker nå</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="54" />
        <location filename="../../ui/pages/roll_test_page.cpp" line="112" />
        <source> g</source>
        <translation> g</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="55" />
        <source>Lead shot actually in this bottle after the tank step, in grams.</source>
        <translation>Blyhagl som faktisk er i denne flasken etter tanktrinnet, i gram.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="58" />
        <source>Fill in the tank-step &amp;result</source>
        <translation>Fyll inn &amp;resultatet fra tanktrinnet</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="60" />
        <source>Copy the bottle contents the tank step recommended (edit them if you set something else).</source>
        <translation>Kopier flaskeinnholdet tanktrinnet anbefalte (rett dem hvis du satte noe annet).</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="66" />
        <source>Roll &amp;test done</source>
        <translation>Rull&amp;test utført</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="68" />
        <source>Untick to compute without a roll test (the CG height then comes from the profile).</source>
        <translation>Fjern krysset for å beregne uten rulltest (tyngdepunktets høyde tas da fra profilen).</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="69" />
        <location filename="../../ui/pages/roll_test_page.cpp" line="118" />
        <location filename="../../ui/pages/roll_test_page.cpp" line="178" />
        <source> rad</source>
        <translation> rad</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="70" />
        <source>m_roll with nothing hung, in radians as the glider reports it (starboard down positive).</source>
        <translation>m_roll uten noe hengt på, i radianer slik glideren rapporterer (styrbord ned positiv).</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="71" />
        <source> m</source>
        <translation> m</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="72" />
        <source>Horizontal distance from the hull axis to where the mass hangs (the hull radius for a mass on the rail).</source>
        <translation>Horisontal avstand fra skrogaksen til der massen henger (skrogradien for en masse på skinnen).</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="76" />
        <source>Mass hung</source>
        <translation>Hengt masse</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="76" />
        <source>Rail</source>
        <translation>Skinne</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="76" />
        <source>m_roll reading</source>
        <translation>m_roll-avlesning</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="79" />
        <source>One row per applied mass: its submerged mass, the rail it hangs on and m_roll with it hanging.</source>
        <translation>Én rad per påhengt masse: massen i vann, skinnen den henger på og m_roll mens den henger.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="80" />
        <source>&amp;Add mass</source>
        <translation>&amp;Legg til masse</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="82" />
        <source>Add a row for another applied mass.</source>
        <translation>Legg til en rad for enda en påhengt masse.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="85" />
        <source>Re&amp;move last</source>
        <translation>Fjern &amp;siste</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="87" />
        <source>Remove the last applied mass.</source>
        <translation>Fjern den siste påhengte massen.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="90" />
        <source>Roll readings</source>
        <translation>Rullavlesninger</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="94" />
        <source>&amp;Initial roll:</source>
        <translation>&amp;Startrull:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="95" />
        <source>&amp;Lever arm:</source>
        <translation>&amp;Momentarm:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="104" />
        <source>Disk weights and roll battery now</source>
        <translation>Skivevekter og rullbatteri nå</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="107" />
        <source>Top</source>
        <translation>Øverst</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="108" />
        <source>Bottom</source>
        <translation>Nederst</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="110" />
        <source>Column %1</source>
        <translation>Kolonne %1</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="113" />
        <source>Disk weight in this seat, in grams (0 = empty).</source>
        <translation>Skivevekt i dette setet, i gram (0 = tomt).</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="119" />
        <source>Roll battery angle now; positive = swung to starboard.</source>
        <translation>Rullbatteriets vinkel nå; positiv = dreid mot styrbord.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="120" />
        <source>Battery:</source>
        <translation>Batteri:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="170" />
        <source> kg</source>
        <translation> kg</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="171" />
        <source>Submerged (apparent) mass of the weight you hung, in kg.</source>
        <translation>Massen i vann (tilsynelatende) av vekten du hengte på, i kg.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="174" />
        <source>Port</source>
        <translation>Babord</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="175" />
        <source>Starboard</source>
        <translation>Styrbord</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="176" />
        <source>The wing rail the mass hangs on.</source>
        <translation>Vingeskinnen massen henger på.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="179" />
        <source>m_roll with this mass hanging and the glider at rest, in radians.</source>
        <translation>m_roll med denne massen hengende og glideren i ro, i radianer.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="284" />
        <source>h-arm &lt;b&gt;%1 mm&lt;/b&gt; (each mass: %2 mm; spread %3 mm). G sits &lt;b&gt;%4 mm to %5&lt;/b&gt; of the hull axis and %6 mm below it. Target h-arm %7 mm.</source>
        <translation>h-arm &lt;b&gt;%1 mm&lt;/b&gt; (hver masse: %2 mm; spredning %3 mm). G ligger &lt;b&gt;%4 mm mot %5&lt;/b&gt; fra skrogaksen og %6 mm under den. Mål for h-arm %7 mm.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="290" />
        <source>starboard</source>
        <translation>styrbord</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="290" />
        <source>port</source>
        <translation>babord</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="294" />
        <source>No roll test: the result will use the profile's CG height.</source>
        <translation>Ingen rulltest: resultatet bruker tyngdepunktshøyden fra profilen.</translation>
    </message>
</context>
<context>
    <name>auv::ui::StartPage</name>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="33" />
        <source>Start: configuration and mode</source>
        <translation>Start: konfigurasjon og modus</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="34" />
        <source>Continue a vehicle configuration from the history or start a new one, then choose what to do.</source>
        <translation>Fortsett en fartøykonfigurasjon fra historikken eller start en ny, og velg så hva du vil gjøre.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="43" />
        <source>&amp;Resume</source>
        <translation>&amp;Fortsett</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="45" />
        <source>Continue the unfinished session where you left it.</source>
        <translation>Fortsett den uferdige økten der du slapp.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="48" />
        <source>&amp;Discard</source>
        <translation>&amp;Forkast</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="50" />
        <source>Delete the unfinished session and start afresh.</source>
        <translation>Slett den uferdige økten og begynn på nytt.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="61" />
        <source>Search ID, payload, area, water type or vehicle</source>
        <translation>Søk i ID, nyttelast, område, vanntype eller fartøy</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="62" />
        <source>Type part of a configuration ID, payload note, area, water type or vehicle name.</source>
        <translation>Skriv en del av en konfigurasjons-ID, nyttelastnotat, område, vanntype eller fartøynavn.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="65" />
        <source>&amp;Search:</source>
        <translation>&amp;Søk:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="70" />
        <source>Configuration</source>
        <translation>Konfigurasjon</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="70" />
        <source>Vehicle</source>
        <translation>Fartøy</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="70" />
        <source>Payload</source>
        <translation>Nyttelast</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="70" />
        <source>Area / water</source>
        <translation>Område / vann</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="71" />
        <source>Last activity</source>
        <translation>Siste aktivitet</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="78" />
        <source>Recent configurations, newest first. The first row starts a new configuration.</source>
        <translation>Nylige konfigurasjoner, nyeste først. Første rad starter en ny konfigurasjon.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="80" />
        <source>Last state</source>
        <translation>Siste tilstand</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="91" />
        <source>What do you want to do?</source>
        <translation>Hva vil du gjøre?</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="92" />
        <source>&amp;First mission: weigh the vehicle and compute the ballast change</source>
        <translation>&amp;Første oppdrag: vei fartøyet og beregn ballastendringen</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="94" />
        <source>No mission flown yet with this configuration: crane weighing (AUV) or tank weighing (glider).</source>
        <translation>Ingen oppdrag kjørt ennå med denne konfigurasjonen: kranveiing (AUV) eller tankveiing (glider).</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="95" />
        <source>&amp;Post mission: import a mission log and look at the deviations</source>
        <translation>&amp;Etter oppdrag: importer en oppdragslogg og se på avvikene</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="97" />
        <source>You have a log of a mission flown with this configuration.</source>
        <translation>Du har en logg fra et oppdrag kjørt med denne konfigurasjonen.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="98" />
        <source>P&amp;re mission: plan the next mission from the analysed log</source>
        <translation>Før &amp;neste oppdrag: planlegg neste oppdrag fra den analyserte loggen</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="100" />
        <source>Needs the analysis of a mission, which this version of the wizard does not do yet.</source>
        <translation>Krever analyse av et oppdrag, som denne versjonen av veiviseren ikke gjør ennå.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="135" />
        <source>Cannot resume: %1</source>
        <translation>Kan ikke fortsette: %1</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="149" />
        <source>The history cannot be opened (%1); you can still work, but nothing will be saved.</source>
        <translation>Historikken kan ikke åpnes (%1); du kan fortsatt arbeide, men ingenting blir lagret.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="167" />
        <source>An unfinished session was found (saved %1): %2, configuration %3, at "%4".</source>
        <translation>Fant en uferdig økt (lagret %1): %2, konfigurasjon %3, ved «%4».</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="169" />
        <source>no vehicle yet</source>
        <translation>ikke noe fartøy ennå</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="170" />
        <source>(no ID)</source>
        <translation>(ingen ID)</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="174" />
        <source>An unfinished session was found but cannot be read: %1</source>
        <translation>Fant en uferdig økt, men den kan ikke leses: %1</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="196" />
        <source>created %1</source>
        <translation>opprettet %1</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="204" />
        <source>+ New configuration</source>
        <translation>+ Ny konfigurasjon</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="245" />
        <source>A new configuration: you name it and choose the vehicle on the next page. Only the first-mission mode makes sense until it has flown.</source>
        <translation>En ny konfigurasjon: du gir den navn og velger fartøy på neste side. Bare første oppdrag gir mening før den har vært i sjøen.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="261" />
        <source>&lt;b&gt;%1&lt;/b&gt; - %2, %3</source>
        <translation>&lt;b&gt;%1&lt;/b&gt; - %2, %3</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="270" />
        <source>Installed (%1): %2</source>
        <translation>Montert (%1): %2</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="272" />
        <source>Installed: nothing recorded yet.</source>
        <translation>Montert: ingenting registrert ennå.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="275" />
        <source>Last mission: %1, imported %2</source>
        <translation>Siste oppdrag: %1, importert %2</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="279" />
        <source>Last mission: none yet.</source>
        <translation>Siste oppdrag: ingen ennå.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="281" />
        <source>Last analysis: %1</source>
        <translation>Siste analyse: %1</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="285" />
        <source>Water temperature %1 °C measured %2 (%3 days ago)</source>
        <translation>Vanntemperatur %1 °C målt %2 (for %3 dager siden)</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="291" />
        <source>: older than one month - measure it again before computing (thesis §5.5.3).</source>
        <translation>: eldre enn én måned - mål den på nytt før beregning (avhandlingen §5.5.3).</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="294" />
        <source>: less than a month old, it can be reused.</source>
        <translation>: under en måned gammel, den kan brukes igjen.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="298" />
        <source>No water temperature in the history: measure it before computing.</source>
        <translation>Ingen vanntemperatur i historikken: mål den før beregning.</translation>
    </message>
</context>
<context>
    <name>auv::ui::TankWeighingPage</name>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="22" />
        <source>Bow bottle, &amp;port:</source>
        <translation>Baugflaske, &amp;babord:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="23" />
        <source>Bow bottle, &amp;starboard:</source>
        <translation>Baugflaske, &amp;styrbord:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="24" />
        <source>Aft bottle, &amp;upper:</source>
        <translation>Akterflaske, &amp;øvre:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="25" />
        <source>Aft bottle, &amp;lower:</source>
        <translation>Akterflaske, &amp;nedre:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="26" />
        <source>Wing rail, p&amp;ort:</source>
        <translation>Vingeskinne, b&amp;abord:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="27" />
        <source>Wing rail, s&amp;tarboard:</source>
        <translation>Vingeskinne, s&amp;tyrbord:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="42" />
        <source>Slocum tank weighing</source>
        <translation>Veiing av Slocum i tank</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="43" />
        <source>Hang the glider submerged in the tank from the two spring scales over the bow and aft ballast bottles; read both once it hangs still and level, with no air trapped.</source>
        <translation>Heng glideren nedsenket i tanken i de to fjærvektene over baug- og akterballastflaskene; les av begge når den henger stille og vannrett, uten innestengt luft.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="48" />
        <source>Glider serial number or name, for the record.</source>
        <translation>Gliderens serienummer eller navn, for journalen.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="50" />
        <source> kg</source>
        <translation> kg</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="51" />
        <source>Mass of the complete glider in air (wings and ballast as now), from a calibrated scale.</source>
        <translation>Massen til hele glideren i luft (vinger og ballast som nå), fra en kalibrert vekt.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="52" />
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="55" />
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="91" />
        <source> g</source>
        <translation> g</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="53" />
        <source>Spring scale hanging directly above the bow ballast bottles, glider fully submerged and still. Read it at eye level, in grams.</source>
        <translation>Fjærvekten som henger rett over baugballastflaskene, glideren helt nedsenket og i ro. Les av i øyehøyde, i gram.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="56" />
        <source>Spring scale hanging directly above the aft ballast bottles, read at the same time.</source>
        <translation>Fjærvekten som henger rett over akterballastflaskene, lest av samtidig.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="57" />
        <source>Glider and spring scales</source>
        <translation>Glider og fjærvekter</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="59" />
        <source>Gl&amp;ider:</source>
        <translation>Gl&amp;ider:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="60" />
        <source>&amp;Dry mass:</source>
        <translation>&amp;Tørrmasse:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="61" />
        <source>&amp;Bow scale:</source>
        <translation>&amp;Baugvekt:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="62" />
        <source>&amp;Aft scale:</source>
        <translation>&amp;Aktervekt:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="66" />
        <source>Fresh water</source>
        <translation>Ferskvann</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="67" />
        <source>Salt water</source>
        <translation>Saltvann</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="68" />
        <source>Fresh tank water is taken as 1000 kg/m³ unless you measured it; salt water needs its measured density.</source>
        <translation>Ferskt tankvann regnes som 1000 kg/m³ hvis du ikke har målt det; saltvann krever målt tetthet.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="71" />
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="75" />
        <source> kg/m³</source>
        <translation> kg/m³</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="72" />
        <source>Density of the tank water (hydrometer or CTD).</source>
        <translation>Tettheten til tankvannet (hydrometer eller CTD).</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="73" />
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="77" />
        <source> °C</source>
        <translation> °C</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="74" />
        <source>Tank water temperature next to the glider, at mid depth.</source>
        <translation>Tankvannets temperatur ved glideren, på halvt dyp.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="76" />
        <source>Density of the water the glider will fly in (from a CTD cast or the area's climatology).</source>
        <translation>Tettheten til vannet glideren skal gå i (fra en CTD-profil eller områdets klimatologi).</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="78" />
        <source>Temperature of the deployment water: the aluminium hull shrinks in cold water.</source>
        <translation>Temperaturen i utsettingsvannet: aluminiumsskroget krymper i kaldt vann.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="79" />
        <source>Water</source>
        <translation>Vann</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="81" />
        <source>Tank &amp;water:</source>
        <translation>Tank&amp;vann:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="82" />
        <source>Tank de&amp;nsity:</source>
        <translation>Tank&amp;tetthet:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="83" />
        <source>Tank te&amp;mperature:</source>
        <translation>Tank&amp;temperatur:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="84" />
        <source>Ta&amp;rget density:</source>
        <translation>&amp;Måltetthet:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="85" />
        <source>Tar&amp;get temperature:</source>
        <translation>Mål&amp;temperatur:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="87" />
        <source>Ballast in the glider now</source>
        <translation>Ballast i glideren nå</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="92" />
        <source>Lead shot in this ballast bottle now, in grams (weigh the bottle contents).</source>
        <translation>Blyhagl i denne ballastflasken nå, i gram (vei innholdet i flasken).</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="93" />
        <source>Brass in this wing rail now, in grams.</source>
        <translation>Messing i denne vingeskinnen nå, i gram.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="177" />
        <source>In the tank it displaces &lt;b&gt;%1 kg&lt;/b&gt;; in the target water it is neutral at &lt;b&gt;%2 kg&lt;/b&gt;. It weighs %3 kg, so it is &lt;b&gt;%4 %5&lt;/b&gt;.&lt;br&gt;Tank step: %6.&lt;br&gt;With that done, the bow scale should read &lt;b&gt;%7 g&lt;/b&gt; and the aft scale &lt;b&gt;%8 g&lt;/b&gt;.</source>
        <translation>I tanken fortrenger den &lt;b&gt;%1 kg&lt;/b&gt;; i målvannet er den nøytral ved &lt;b&gt;%2 kg&lt;/b&gt;. Den veier %3 kg, så den er &lt;b&gt;%4 %5&lt;/b&gt;.&lt;br&gt;Tanktrinn: %6.&lt;br&gt;Når det er gjort, skal baugvekten vise &lt;b&gt;%7 g&lt;/b&gt; og aktervekten &lt;b&gt;%8 g&lt;/b&gt;.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="184" />
        <source>g heavy</source>
        <translation>g for tung</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="184" />
        <source>g light</source>
        <translation>g for lett</translation>
    </message>
</context>
<context>
    <name>auv::ui::VehiclePage</name>
    <message>
        <location filename="../../ui/pages/vehicle_page.cpp" line="30" />
        <source>Vehicle and configuration</source>
        <translation>Fartøy og konfigurasjon</translation>
    </message>
    <message>
        <location filename="../../ui/pages/vehicle_page.cpp" line="31" />
        <source>Choose the vehicle and name the payload configuration you are ballasting.</source>
        <translation>Velg fartøy og gi nyttelastkonfigurasjonen du ballasterer et navn.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/vehicle_page.cpp" line="34" />
        <source>The vehicle profile: hull volume, centre of buoyancy, adjustment points and weight kit.</source>
        <translation>Fartøyprofilen: skrogvolum, oppdriftssenter, trimpunkter og vektsett.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/vehicle_page.cpp" line="38" />
        <source>Configuration ID as on the vehicle's ballasting sheet: three groups of letters or digits, e.g. 01-02-03 (vehicle, payload set, water).</source>
        <translation>Konfigurasjons-ID som på fartøyets ballastskjema: tre grupper bokstaver eller sifre, f.eks. 01-02-03 (fartøy, nyttelastsett, vann).</translation>
    </message>
    <message>
        <location filename="../../ui/pages/vehicle_page.cpp" line="40" />
        <source>e.g. 01-02-03</source>
        <translation>f.eks. 01-02-03</translation>
    </message>
    <message>
        <location filename="../../ui/pages/vehicle_page.cpp" line="41" />
        <source>Which payload modules are fitted, in your words.</source>
        <translation>Hvilke nyttelastmoduler som er montert, med dine ord.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/vehicle_page.cpp" line="42" />
        <source>Area of operation, e.g. the fjord or the survey site.</source>
        <translation>Operasjonsområde, f.eks. fjorden eller kartleggingsfeltet.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/vehicle_page.cpp" line="43" />
        <source>Kind of water, e.g. fjord, coastal, open ocean.</source>
        <translation>Type vann, f.eks. fjord, kyst, åpent hav.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/vehicle_page.cpp" line="53" />
        <source>&amp;Vehicle:</source>
        <translation>&amp;Fartøy:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/vehicle_page.cpp" line="54" />
        <source>&amp;Configuration ID:</source>
        <translation>&amp;Konfigurasjons-ID:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/vehicle_page.cpp" line="56" />
        <source>&amp;Payload:</source>
        <translation>&amp;Nyttelast:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/vehicle_page.cpp" line="57" />
        <source>&amp;Area:</source>
        <translation>&amp;Område:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/vehicle_page.cpp" line="58" />
        <source>Water &amp;type:</source>
        <translation>Vann&amp;type:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/vehicle_page.cpp" line="85" />
        <source>From the history.</source>
        <translation>Fra historikken.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/vehicle_page.cpp" line="88" />
        <source>Three groups of 1-8 letters or digits separated by '-', e.g. 01-02-03.</source>
        <translation>Tre grupper med 1-8 bokstaver eller sifre atskilt med «-», f.eks. 01-02-03.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/vehicle_page.cpp" line="91" />
        <source>A new configuration ID.</source>
        <translation>En ny konfigurasjons-ID.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/vehicle_page.cpp" line="98" />
        <source>%1: %2 kg in air, hull volume %3 m³, %4 adjustment points; weighed by %5.</source>
        <translation>%1: %2 kg i luft, skrogvolum %3 m³, %4 trimpunkter; veies med %5.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/vehicle_page.cpp" line="103" />
        <source>the tank method (spring scales)</source>
        <translation>tankmetoden (fjærvekter)</translation>
    </message>
    <message>
        <location filename="../../ui/pages/vehicle_page.cpp" line="103" />
        <source>crane scales</source>
        <translation>kranvekter</translation>
    </message>
</context>
<context>
    <name>auv::ui::WaterPage</name>
    <message>
        <location filename="../../ui/pages/water_page.cpp" line="32" />
        <source>Fresh water (about 0.5)</source>
        <translation>Ferskvann (ca. 0,5)</translation>
    </message>
    <message>
        <location filename="../../ui/pages/water_page.cpp" line="33" />
        <source>Brackish, mildly (1-5)</source>
        <translation>Svakt brakkvann (1-5)</translation>
    </message>
    <message>
        <location filename="../../ui/pages/water_page.cpp" line="34" />
        <source>Brackish, moderately (5-15)</source>
        <translation>Moderat brakkvann (5-15)</translation>
    </message>
    <message>
        <location filename="../../ui/pages/water_page.cpp" line="35" />
        <source>Brackish, heavily (15-30)</source>
        <translation>Sterkt brakkvann (15-30)</translation>
    </message>
    <message>
        <location filename="../../ui/pages/water_page.cpp" line="36" />
        <source>Sea water (about 35)</source>
        <translation>Sjøvann (ca. 35)</translation>
    </message>
    <message>
        <location filename="../../ui/pages/water_page.cpp" line="42" />
        <source>Mission water</source>
        <translation>Oppdragsvann</translation>
    </message>
    <message>
        <location filename="../../ui/pages/water_page.cpp" line="43" />
        <source>Where will the vehicle fly? Density includes pressure at the operating depth.</source>
        <translation>Hvor skal fartøyet gå? Tettheten tar med trykket på operasjonsdybden.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/water_page.cpp" line="45" />
        <source>Water temperature at the operating depth if you know it (CTD cast), else at the surface.</source>
        <translation>Vanntemperatur på operasjonsdybden hvis du kjenner den (CTD-profil), ellers i overflaten.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/water_page.cpp" line="48" />
        <source>Measured salinity</source>
        <translation>Målt saltholdighet</translation>
    </message>
    <message>
        <location filename="../../ui/pages/water_page.cpp" line="50" />
        <source>Pick a water type if you have no salinity measurement (thesis Table 2.1).</source>
        <translation>Velg en vanntype hvis du ikke har målt saltholdigheten (avhandlingen tabell 2.1).</translation>
    </message>
    <message>
        <location filename="../../ui/pages/water_page.cpp" line="52" />
        <source>Practical salinity of the mission water.</source>
        <translation>Praktisk saltholdighet i oppdragsvannet.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/water_page.cpp" line="53" />
        <source>Depth where the vehicle spends most of the mission.</source>
        <translation>Dybden der fartøyet er mesteparten av oppdraget.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/water_page.cpp" line="54" />
        <source>Latitude of the area (gravity for depth to pressure).</source>
        <translation>Områdets breddegrad (tyngdekraft for dybde til trykk).</translation>
    </message>
    <message>
        <location filename="../../ui/pages/water_page.cpp" line="61" />
        <source>&amp;Temperature:</source>
        <translation>&amp;Temperatur:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/water_page.cpp" line="62" />
        <source>Water t&amp;ype:</source>
        <translation>Vann&amp;type:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/water_page.cpp" line="63" />
        <source>&amp;Salinity:</source>
        <translation>&amp;Saltholdighet:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/water_page.cpp" line="64" />
        <source>Operating &amp;depth:</source>
        <translation>Operasjons&amp;dybde:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/water_page.cpp" line="65" />
        <source>&amp;Latitude:</source>
        <translation>&amp;Breddegrad:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/water_page.cpp" line="66" />
        <source>In-situ density:</source>
        <translation>Tetthet in situ:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/water_page.cpp" line="93" />
        <source>%1 kg/m³ at %2 dbar</source>
        <translation>%1 kg/m³ ved %2 dbar</translation>
    </message>
</context>
<context>
    <name>auv::ui::WeightMapWidget</name>
    <message>
        <location filename="../../ui/widgets/weight_map_widget.cpp" line="16" />
        <source>Top view, bow to the right. Green: add, red: remove, grey: installed now.</source>
        <translation>Sett ovenfra, baugen til høyre. Grønn: legg til, rød: fjern, grå: montert nå.</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/weight_map_widget.cpp" line="50" />
        <source>bow ▶</source>
        <translation>baug ▶</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/weight_map_widget.cpp" line="51" />
        <source>starboard ▼</source>
        <translation>styrbord ▼</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/weight_map_widget.cpp" line="58" />
        <source>CB</source>
        <translation>CB</translation>
    </message>
</context>
</TS>