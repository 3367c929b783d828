<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="nb_NO">
<context>
    <name>Advice</name>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="23"/>
        <source>No steady dive or climb long enough was found: nothing to estimate from.</source>
        <translation>Fant ingen stødig dykk eller stigning som var lang nok: ingenting å estimere fra.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="24"/>
        <source>No steady level flight of at least %1 s was found: errors and estimates are not available.</source>
        <translation>Fant ingen stødig planflyging på minst %1 s: avvik og estimater er ikke tilgjengelige.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="25"/>
        <source>%1: %2 interval(s), %3 s left out of the steady windows.</source>
        <translation>%1: %2 intervall, %3 s holdt utenfor de stødige vinduene.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="26"/>
        <source>%1 leg(s) where the vehicle swung slowly up and down were averaged over whole swings.</source>
        <translation>%1 etappe(r) der fartøyet svingte sakte opp og ned ble midlet over hele svingninger.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="136"/>
        <source>The analysed log was not flown as commanded (see its warnings), so this move rests on a net buoyancy uncertainty of ±%2 kg: after the move, make a short test dive at the survey&apos;s speeds before the survey.</source>
        <translation>Den analyserte loggen ble ikke fløyet som beordret (se advarslene), så denne flyttingen hviler på en usikkerhet i netto oppdrift på ±%2 kg: etter flyttingen, ta et kort prøvedykk ved kartleggingens hastigheter før kartleggingen.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="27"/>
        <source>For %1 min the vehicle stayed about %2 m above its commanded depth with the elevator at its stop (%3°): it is too light or too tail-heavy for its planes at this speed, so this log says little about its ballast. Add weight at the front in a small step and make a short test dive before a survey.</source>
        <translation>I %1 min holdt fartøyet seg omtrent %2 m over beordret dybde med høyderoret i anslag (%3°): det er for lett eller for akterlastet for rorene ved denne farten, så denne loggen sier lite om ballasten. Legg til vekt forut i et lite steg og ta et kort prøvedykk før en kartlegging.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="28"/>
        <source>For %1 min the vehicle stayed about %2 m below its commanded depth with the elevator at its stop (%3°): it is too heavy or too nose-heavy for its planes at this speed, so this log says little about its ballast. Remove weight at the front in a small step and make a short test dive before a survey.</source>
        <translation>I %1 min holdt fartøyet seg omtrent %2 m under beordret dybde med høyderoret i anslag (%3°): det er for tungt eller for forlastet for rorene ved denne farten, så denne loggen sier lite om ballasten. Fjern vekt forut i et lite steg og ta et kort prøvedykk før en kartlegging.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="29"/>
        <source>In %1 leg(s), %2 min in all, the vehicle porpoised (pitch swinging by up to %3° every %4 s or so) and never flew steadily: the depth autopilot overreacts on this vehicle, so the estimate comes from the rest of the log. Lower the depth autopilot&apos;s gains or lower the centre of gravity; moving weights forward or aft will not stop it.</source>
        <translation>I %1 etappe(r), %2 min i alt, gikk fartøyet i bølgebevegelse (stamp som svinger med opptil %3° omtrent hvert %4 s) og fløy aldri stødig: dybdeautopiloten overreagerer på dette fartøyet, så estimatet kommer fra resten av loggen. Senk dybdeautopilotens forsterkning eller senk tyngdepunktet; å flytte vekter forover eller akterover vil ikke stoppe det.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="30"/>
        <source>The legs fit one steady balance only with the pitch sensor reading %1 ± %2° more than the vehicle&apos;s pitch (reading minus true; its prior 0 ± %3°). The net buoyancy, CG and predicted flight pitch are of the true attitude; the logged pitch is not. Align the sensor, or keep the bias by accepting it in the model check.</source>
        <translation>Etappene passer med én stasjonær balanse bare når stampsensoren leser %1 ± %2° mer enn fartøyets stamp (avlest minus sann; forhåndsantakelse 0 ± %3°). Netto oppdrift, tyngdepunkt og forventet stamp i fart gjelder den sanne attityden; den loggførte stampen gjør det ikke. Juster sensoren, eller behold skjevheten ved å godta den i modellsjekken.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="31"/>
        <source>The logged pitch and roll were corrected by the attitude sensor errors an earlier model check found and you accepted: pitch %1 ± %2°, roll %3 ± %4° (reading minus true). Their uncertainty is included in the net buoyancy and CG uncertainty.</source>
        <translation>Loggført stamp og rull ble korrigert for feilene i attitydesensoren som en tidligere modellsjekk fant og du godtok: stamp %1 ± %2°, rull %3 ± %4° (avlest minus sann). Usikkerheten deres er tatt med i usikkerheten for netto oppdrift og tyngdepunkt.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="32"/>
        <source>measured minus commanded, during glides whose command has the phase&apos;s sign</source>
        <translation>målt minus beordret, i glid der ordren har fasens fortegn</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="33"/>
        <source>measured minus commanded, in steady level flight</source>
        <translation>målt minus beordret, i stødig planflyging</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="34"/>
        <source>pitch at steady depth (the log has no commanded pitch; level flight should be at 0°)</source>
        <translation>stamp på stødig dybde (loggen har ingen beordret stamp; planflyging skal være på 0°)</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="35"/>
        <source>The log has no commanded depth: the depth error is not available.</source>
        <translation>Loggen har ingen beordret dybde: dybdeavviket er ikke tilgjengelig.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="36"/>
        <source>%1 CTD samples outside the EOS-80 range were not used for the density.</source>
        <translation>%1 CTD-målinger utenfor gyldighetsområdet til EOS-80 ble ikke brukt til tettheten.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="37"/>
        <source>No in-situ density could be computed (no temperature and salinity or density in the log): %1 kg/m³ assumed.</source>
        <translation>Kunne ikke beregne tetthet in situ (loggen har verken temperatur og saltholdighet eller tetthet): %1 kg/m³ er antatt.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="38"/>
        <source>Not identifiable from this log: a glider&apos;s pitch is set by its battery position, not by a fixed CG (use the tank or pitch-trim procedure).</source>
        <translation>Kan ikke bestemmes fra denne loggen: en glider sin stamp settes av batteriposisjonen, ikke av et fast tyngdepunkt (bruk tank- eller stamptrimprosedyren).</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="39"/>
        <source>Not identifiable from this log: the glider&apos;s roll is set by its roll mass (use the tank procedure).</source>
        <translation>Kan ikke bestemmes fra denne loggen: gliderens rull settes av rullevekten (bruk tankprosedyren).</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="40"/>
        <source>Not identifiable from this log: it has no pump volume (the buoyancy engine&apos;s volume).</source>
        <translation>Kan ikke bestemmes fra denne loggen: den har ikke pumpevolum (oppdriftsmotorens volum).</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="41"/>
        <source>Not identifiable from this log: it has no pitch.</source>
        <translation>Kan ikke bestemmes fra denne loggen: den har ikke stamp.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="42"/>
        <source>Not identifiable from this log: no steady dive or climb was found.</source>
        <translation>Kan ikke bestemmes fra denne loggen: fant ingen stødig dykk eller stigning.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="43"/>
        <source>Not identifiable from this log: fewer than 10 steady-glide samples deeper than %1 m with a pitch of at least %2°.</source>
        <translation>Kan ikke bestemmes fra denne loggen: færre enn 10 målinger i stødig glid dypere enn %1 m med stamp på minst %2°.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="44"/>
        <source>The log gives the mass as %1 kg but the vehicle profile has %2 kg: the fit uses the profile&apos;s mass (it matters only through density changes).</source>
        <translation>Loggen oppgir massen som %1 kg, men fartøyprofilen har %2 kg: tilpasningen bruker profilens masse (den betyr bare noe gjennom tetthetsendringer).</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="45"/>
        <source>The glider flight-model fit did not converge: %1</source>
        <translation>Tilpasningen av gliderens flymodell konvergerte ikke: %1</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="46"/>
        <source>The glider flight-model constants are the Slocum defaults (wing area 0.1 m², lift slope 7.53 per rad, induced drag 10.5 per rad²): give this glider&apos;s flight model in its vehicle profile.</source>
        <translation>Konstantene i gliderens flymodell er standardverdiene for Slocum (vingeareal 0,1 m², løftestigning 7,53 per rad, indusert motstand 10,5 per rad²): legg inn denne gliderens flymodell i fartøyprofilen.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="47"/>
        <source>The hull compressibility is not in the vehicle profile: 5e-6 per dbar is used.</source>
        <translation>Skrogets kompressibilitet står ikke i fartøyprofilen: 5e-6 per dbar brukes.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="48"/>
        <source>Not identifiable from this log: no steady segment has roll samples.</source>
        <translation>Kan ikke bestemmes fra denne loggen: ingen stødige segmenter har rullmålinger.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="49"/>
        <source>The log has no propeller speed: CG y assumes the roll at cruise is static; any propeller reaction torque is included in it.</source>
        <translation>Loggen har ikke propellturtall: tyngdepunkt y antar at rullen i marsjfart er statisk; et eventuelt reaksjonsmoment fra propellen er tatt med i den.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="50"/>
        <source>All steady segments run the propeller at about the same speed, so its reaction torque cannot be told from a CG offset: CG y is the offset that levels the vehicle at this cruise speed, not the static CG.</source>
        <translation>Alle stødige segmenter kjører propellen på omtrent samme turtall, så reaksjonsmomentet kan ikke skilles fra et forskjøvet tyngdepunkt: tyngdepunkt y er forskyvningen som holder fartøyet på rett kjøl i denne marsjfarten, ikke det statiske tyngdepunktet.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="51"/>
        <source>Not identifiable from this log: a steady roll gives y = BG tan(roll), and BG (the CG height below the CB) cannot be measured from the log. Enter BG from an inclining or roll test for this configuration (static roll %1°).</source>
        <translation>Kan ikke bestemmes fra denne loggen: en stødig rull gir y = BG tan(rull), og BG (tyngdepunktets høyde under oppdriftssenteret) kan ikke måles fra loggen. Legg inn BG fra en krengeprøve eller rulletest for denne konfigurasjonen (statisk rull %1°).</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="52"/>
        <source>Not identifiable from this log: no steady level flight long enough was found.</source>
        <translation>Kan ikke bestemmes fra denne loggen: fant ingen stødig planflyging som var lang nok.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="53"/>
        <source>Not identifiable from this log: it has no speed (the lift and moment that balance the buoyancy grow with the speed squared).</source>
        <translation>Kan ikke bestemmes fra denne loggen: den har ikke fart (løftet og momentet som balanserer oppdriften vokser med kvadratet av farten).</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="54"/>
        <source>Not identifiable from this log: no steady segment has both speed and pitch.</source>
        <translation>Kan ikke bestemmes fra denne loggen: ingen stødige segmenter har både fart og stamp.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="55"/>
        <source>Not identifiable from this log: it has no elevator (stern-plane) angle, so each steady segment only fixes a moment about the planes&apos; centre of pressure (%1 m from the CB). Record the elevator angle.</source>
        <translation>Kan ikke bestemmes fra denne loggen: den har ikke dybderorvinkel, så hvert stødige segment bestemmer bare et moment om rorenes trykksenter (%1 m fra oppdriftssenteret). Logg dybderorvinkelen.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="56"/>
        <source>Calibrated with %1 steady segments of earlier missions of this configuration and the known weight changes since.</source>
        <translation>Kalibrert med %1 stødige segmenter fra tidligere oppdrag med denne konfigurasjonen og de kjente vektendringene siden.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="57"/>
        <source>The earlier mission of configuration %1 could not be read from the history (%2): this log is analysed alone, without the known weight change since.</source>
        <translation>Det tidligere oppdraget med konfigurasjon %1 kunne ikke leses fra historikken (%2): denne loggen analyseres alene, uten den kjente vektendringen siden.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="58"/>
        <source>%1 steady segment(s) left out: the tunnel thrusters ran there (up to %2 rpm), and the steady balance has no thruster term (the model check replays them).</source>
        <translation>%1 stødige segment(er) utelatt: tunnelthrusterne gikk der (opptil %2 o/min), og den stødige balansen har ikke noe thrusterledd (modellsjekken spiller dem av igjen).</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="59"/>
        <source>Not identifiable from this log: the tunnel thrusters ran in all %1 steady segment(s) (up to %2 rpm) and carry an unknown part of the net buoyancy, which the steady balance has no term for. Fly steady legs above the thrusters&apos; hand-over speed, or use the model check, which replays them.</source>
        <translation>Ikke identifiserbart fra denne loggen: tunnelthrusterne gikk i alle %1 stødige segment(er) (opptil %2 o/min) og bærer en ukjent del av netto oppdrift, som den stødige balansen ikke har noe ledd for. Fly stødige etapper over thrusternes overgangsfart, eller bruk modellsjekken, som spiller dem av igjen.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="60"/>
        <source>%1 dive(s) or climb(s) held a steady pitch but did not fit the balance the other legs calibrated (the depth changed at a pitch and elevator no steady flight has): left out of the estimate.</source>
        <translation>%1 dykk eller stigning(er) holdt stødig stamp, men passet ikke med balansen de andre etappene kalibrerte (dybden endret seg ved en stamp og et dybderor som ingen stødig flyging har): utelatt fra estimatet.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="61"/>
        <source>The depth steps and speed changes disagreed among themselves more than they added (net buoyancy ± %1 kg with them, ± %2 kg from the steady segments alone): the estimate is the steady segments&apos;.</source>
        <translation>Dybdetrinnene og fartsendringene var mer uenige seg imellom enn de tilførte (netto oppdrift ± %1 kg med dem, ± %2 kg fra de stødige segmentene alene): estimatet er de stødige segmentenes.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="62"/>
        <source>The log put %1 at %2 where the profile has %3 ± %4: more than three prior sigmas away, which no vehicle of this class has, so the steady balance did not describe this log (a pitch sensor bias, legs that were not steady, or a profile of another vehicle). The net buoyancy and CG rest on that balance: check the attitude sensor&apos;s alignment and the profile before moving weights.</source>
        <translation>Loggen la %1 på %2 der profilen har %3 ± %4: mer enn tre a priori-sigma unna, noe ingen fartøy i denne klassen har, så den stødige balansen beskrev ikke denne loggen (en skjevhet i stampesensoren, etapper som ikke var stødige, eller en profil for et annet fartøy). Netto oppdrift og tyngdepunkt hviler på den balansen: kontroller innrettingen av attitydesensoren og profilen før du flytter lodd.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="63"/>
        <source>The depth steps and speed changes were not flown again: the vehicle did not fly as commanded (too light or porpoising), and there the replay fits the plane stop and the autopilot instead of the hydrodynamics. The estimate is the steady segments&apos;.</source>
        <translation>Dybdetrinnene og fartsendringene ble ikke fløyet på nytt: fartøyet fløy ikke som kommandert (for lett eller porpoising), og der tilpasser gjenavspillingen rorstoppet og autopiloten i stedet for hydrodynamikken. Estimatet er de stødige segmentenes.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="64"/>
        <source>The depth steps and speed changes were not flown again: the earlier missions and the known weight changes calibrate the vehicle, and the replay added model error, not information.</source>
        <translation>Dybdetrinnene og fartsendringene ble ikke fløyet på nytt: de tidligere oppdragene og de kjente vektendringene kalibrerer fartøyet, og gjenavspillingen tilførte modellfeil, ikke informasjon.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="65"/>
        <source>Not identifiable from this log: the steady segments do not determine the heave and pitch balance.</source>
        <translation>Kan ikke bestemmes fra denne loggen: de stødige segmentene bestemmer ikke balansen i hiv og stamp.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="66"/>
        <source>Elevator zero offset assumed 0 ± %1° (included in the uncertainties): the steady segments do not span enough speeds to tell it from the net buoyancy.</source>
        <translation>Dybderorets nullpunktsavvik er antatt 0 ± %1° (tatt med i usikkerhetene): de stødige segmentene spenner ikke over nok hastigheter til å skille det fra netto oppdrift.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="67"/>
        <source>The plane coefficients were converted to the log&apos;s elevator sign (trailing edge down positive).</source>
        <translation>Rorkoeffisientene ble regnet om til loggens fortegn for dybderoret (bakkant ned positiv).</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="68"/>
        <source>The vehicle&apos;s hydrodynamics were calibrated together with the ballast state (%1 parameters determined by the log).</source>
        <translation>Fartøyets hydrodynamikk ble kalibrert sammen med ballasttilstanden (%1 parametere bestemt av loggen).</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="69"/>
        <source>The uncertainties come from that calibration (%1 % prior uncertainty per group of hydrodynamic coefficients).</source>
        <translation>Usikkerhetene kommer fra den kalibreringen (%1 % usikkerhet på forhånd per gruppe av hydrodynamiske koeffisienter).</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="70"/>
        <source>The uncertainties come from that calibration (%1 % prior uncertainty per group of hydrodynamic coefficients; the Munk moment&apos;s form unknown).</source>
        <translation>Usikkerhetene kommer fra den kalibreringen (%1 % usikkerhet på forhånd per gruppe av hydrodynamiske koeffisienter; formen på Munk-momentet er ukjent).</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="71"/>
        <source>BG from the vehicle profile (%1 mm ± %2 %) sets the scale of the pitch moments; BG from a roll test sharpens CG x.</source>
        <translation>BG fra fartøyprofilen (%1 mm ± %2 %) bestemmer skalaen på stampmomentene; BG fra en rulletest gjør tyngdepunkt x skarpere.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="72"/>
        <source>Once trimmed, the vehicle should cruise at %1 m/s at %2 rpm (this log: %3 m/s); the propeller torque there changes by %4 N m, and the roll the plan levels includes it (CG y at cruise %5 mm).</source>
        <translation>Når fartøyet er trimmet, bør det gå %1 m/s ved %2 o/min (denne loggen: %3 m/s); propellmomentet endres der med %4 N m, og rullingen planen retter opp tar det med (tyngdepunkt y i marsj %5 mm).</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="77"/>
        <source>%1: no change (%2 stays).</source>
        <translation>%1: ingen endring (%2 blir).</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="78"/>
        <source>Priorities (thesis §5.4): net buoyancy %1 to %2 and never negative, then pitch within ±%3, then roll within ±%4; %5 piece(s) to handle.</source>
        <translation>Prioriteringer (avhandlingen §5.4): netto oppdrift %1 til %2 og aldri negativ, deretter stamp innenfor ±%3, deretter rull innenfor ±%4; %5 lodd å håndtere.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="79"/>
        <source>After the move: net buoyancy %1, pitch %2, roll %3.</source>
        <translation>Etter flyttingen: netto oppdrift %1, stamp %2, rull %3.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="80"/>
        <source>Half-way policy: this move aims at about half of the needed change (net buoyancy %1 to %2, pitch %3, roll %4); check the vehicle again and repeat.</source>
        <translation>Halvveis-strategi: denne flyttingen sikter mot omtrent halvparten av nødvendig endring (netto oppdrift %1 til %2, stamp %3, rull %4); kontroller fartøyet igjen og gjenta.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="82"/>
        <source>The four scale readings add up to %1 but the hook reads %2 (tolerance %3): the CG uses the four readings, the mass uses the hook.</source>
        <translation>De fire vekttallene blir til sammen %1, men kroken viser %2 (toleranse %3): tyngdepunktet bruker de fire tallene, massen bruker kroken.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="83"/>
        <source>h = %1 is implausibly large for a glider (about 6 mm is usual): check the roll signs and which rail the mass hung on.</source>
        <translation>h = %1 er urimelig stor for en glider (omkring 6 mm er vanlig): kontroller fortegnene på rullen og hvilken skinne loddet hang på.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="84"/>
        <source>The single h values spread by %1 (%2 of the mean): repeat the roll test.</source>
        <translation>De enkelte h-verdiene sprer med %1 (%2 av middelverdien): gjenta rulletesten.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="85"/>
        <source>The bottles cannot hold the level split (bow %1, aft %2): the glider will not float level. Move a disk or rail weight.</source>
        <translation>Flaskene kan ikke ta den vannrette fordelingen (baug %1, akter %2): glideren vil ikke flyte vannrett. Flytt en skive eller et skinnelodd.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="86"/>
        <source>The bottles are full: %1 more is needed for neutral, so the glider stays light. Add ballast elsewhere.</source>
        <translation>Flaskene er fulle: %1 til trengs for nøytral oppdrift, så glideren forblir lett. Legg ballast et annet sted.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="87"/>
        <source>The bottles are empty: %1 more must come out, so the glider stays HEAVY. Remove a disk or rail weight.</source>
        <translation>Flaskene er tomme: %1 til må ut, så glideren forblir TUNG. Ta ut en skive eller et skinnelodd.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="89"/>
        <source>The CG is not below the CB with the BG of the vehicle profile: the vehicle would capsize. Check BG in the vehicle profile.</source>
        <translation>Tyngdepunktet ligger ikke under oppdriftssenteret med BG fra fartøyprofilen: fartøyet ville kantre. Kontroller BG i fartøyprofilen.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="90"/>
        <source>In the tank (%1, %2) the glider displaces %3 (%4); at %5 the hull measures %6 and is neutral at %7 in %8 water.</source>
        <translation>I tanken (%1, %2) fortrenger glideren %3 (%4); ved %5 måler skroget %6 og er nøytralt ved %7 i vann på %8.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="91"/>
        <source>It weighs %1, so it is %2 light: the bottles change by %3 (rounded down to whole grams so it never ends heavy).</source>
        <translation>Den veier %1, så den er %2 for lett: flaskene endres med %3 (rundet ned til hele gram så den aldri ender tung).</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="92"/>
        <source>It weighs %1, so it is %2 heavy: the bottles change by %3 (rounded down to whole grams so it never ends heavy).</source>
        <translation>Den veier %1, så den er %2 for tung: flaskene endres med %3 (rundet ned til hele gram så den aldri ender tung).</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="93"/>
        <source>Bow bottles: %1 in %2 and %3 in %4 (%5), so the bow scale would read %6 and the glider floats level.</source>
        <translation>Baugflasker: %1 i %2 og %3 i %4 (%5), så baugvekten ville vise %6 og glideren flyter plant.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="94"/>
        <source>Aft bottles: %1 in %2 and %3 in %4 (%5), so the aft scale would read %6 and the glider floats level.</source>
        <translation>Akterflasker: %1 i %2 og %3 i %4 (%5), så aktervekten ville vise %6 og glideren flyter plant.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="95"/>
        <source>No roll test recorded: set the bottles, hang the glider for the roll test (report 4.2) and enter it on the roll-test page; until then the CG height is the profile&apos;s BG.</source>
        <translation>Ingen rulletest registrert: sett flaskene, heng opp glideren for rulletesten (rapport 4.2) og før den inn på rulletestsiden; inntil da er tyngdepunktets høyde profilens BG.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="96"/>
        <source>Roll test: h = %1 from %2 hung masses, so G sits %3 to %4 of B and %5 below it.</source>
        <translation>Rulletest: h = %1 fra %2 opphengte masser, så G ligger %3 mot %4 av B og %5 under den.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="97"/>
        <source>Move %1 of rail weight from the %2 wing rail: the battery alone cannot reach the roll.</source>
        <translation>Flytt %1 skinnevekt fra %2 vingeskinne: batteriet alene kan ikke nå rullen.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="98"/>
        <source>Move %1 of lead from the %2 bow bottle: the battery cannot reach the roll.</source>
        <translation>Flytt %1 bly fra %2 baugflaske: batteriet kan ikke nå rullen.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="99"/>
        <source>Move %1 of lead from the %2 bow bottle: the battery and wing rails cannot reach the roll.</source>
        <translation>Flytt %1 bly fra %2 baugflaske: batteriet og vingeskinnene kan ikke nå rullen.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="100"/>
        <source>Set the roll battery to %1 (%2, toward %3; now %4) to bring G straight below B.</source>
        <translation>Sett rullbatteriet til %1 (%2, mot %3; nå %4) for å bringe G rett under B.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="101"/>
        <source>The battery, wing rails and bow bottles together cannot cancel the roll: %1 remains. Move other masses sideways.</source>
        <translation>Batteriet, vingeskinnene og baugflaskene kan ikke sammen oppheve rullen: %1 gjenstår. Flytt andre masser sideveis.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="102"/>
        <source>Swap disk column %1 (%2 top, %3 bottom), which %4 G by %5.</source>
        <translation>Bytt om skivesøyle %1 (%2 øverst, %3 nederst), som %4 G med %5.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="103"/>
        <source>Move %1 of lead from the %2 aft bottle, so h goes from %3 to %4 (target %5).</source>
        <translation>Flytt %1 bly fra %2 akterflaske, så h går fra %3 til %4 (mål %5).</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="104"/>
        <source>The h-arm target %1 cannot be reached with the disk weights and aft bottles; best is %2 (arrangement %3).</source>
        <translation>Målet for h-armen %1 kan ikke nås med skivevektene og akterflaskene; best er %2 (oppsett %3).</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="105"/>
        <source>The predicted net buoyancy %1 is below the profile&apos;s band: the glider would end HEAVY.</source>
        <translation>Forventet netto oppdrift %1 er under profilens bånd: glideren ville ende TUNG.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="106"/>
        <source>The predicted net buoyancy %1 is above the profile&apos;s band.</source>
        <translation>Forventet netto oppdrift %1 er over profilens bånd.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="107"/>
        <source>The predicted pitch %1 is outside ±%2.</source>
        <translation>Forventet stamp %1 er utenfor ±%2.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="108"/>
        <source>The predicted roll %1 is outside ±%2.</source>
        <translation>Forventet rull %1 er utenfor ±%2.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="110"/>
        <source>What is in the bottles was not given: their capacities are checked against half-full bottles. Enter what is installed to check them.</source>
        <translation>Innholdet i flaskene ble ikke oppgitt: kapasitetene kontrolleres mot halvfulle flasker. Før inn hva som er montert for å kontrollere dem.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="111"/>
        <source>The wing rails cannot take the whole roll correction (%1 g); move the roll battery or a disk weight for the rest.</source>
        <translation>Vingeskinnene kan ikke ta hele rullkorreksjonen (%1 g); flytt rullbatteriet eller en skivevekt for resten.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="112"/>
        <source>the pitch trim (the log has no battery position, or it varies too little): the bottle split is Baird&apos;s level split only</source>
        <translation>stamptrimmen (loggen har ingen batteriposisjon, eller den varierer for lite): fordelingen på flaskene er bare Bairds plane fordeling</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="113"/>
        <source>the roll (the log has no roll in glides)</source>
        <translation>rullen (loggen har ingen rull under gliding)</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="114"/>
        <source>C_PITCH (the log has no pitch-mass position with enough variation)</source>
        <translation>C_PITCH (loggen har ingen posisjon for stampmassen med nok variasjon)</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="115"/>
        <source>where the grams go: the log carries no geometry of the ballast places; add %1 g at the vehicle&apos;s ballast places so that it stays level</source>
        <translation>hvor grammene skal: loggen har ingen geometri for ballaststedene; legg %1 g på fartøyets ballaststeder slik at det holder seg plant</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="116"/>
        <source>the ballast (pump) zero offset in the vendor&apos;s setting: only the mass change is known</source>
        <translation>ballastens (pumpens) nullpunktsforskyvning i produsentens innstilling: bare masseendringen er kjent</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="119"/>
        <source>No change: the vehicle is already as good as the kit allows.</source>
        <translation>Ingen endring: fartøyet er allerede så godt som vektsettet tillater.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="120"/>
        <source>Next mission at %1: from net buoyancy %2, pitch %3, roll %4 to %5 ± %6, pitch %7 ± %8, roll %9 ± %10 (1 σ).</source>
        <translation>Neste oppdrag ved %1: fra netto oppdrift %2, stamp %3, rull %4 til %5 ± %6, stamp %7 ± %8, rull %9 ± %10 (1 σ).</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="121"/>
        <source>Mass %1 from the last mission: %2 displaced at %3, %4, %5 minus the measured net buoyancy %6.</source>
        <translation>Masse %1 fra forrige oppdrag: %2 fortrengt ved %3, %4, %5 minus målt netto oppdrift %6.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="122"/>
        <source>Safety margin %1 = %2 × σ %3 (estimate and water): the change keeps at least that much net buoyancy at every planned point.</source>
        <translation>Sikkerhetsmargin %1 = %2 × σ %3 (estimat og vann): endringen beholder minst så mye netto oppdrift i hvert planlagte punkt.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="123"/>
        <source>CG x was not identified from the log: the plan assumes it at the CB and keeps the fore-aft balance. Check pitch on the next mission.</source>
        <translation>Tyngdepunkt x ble ikke bestemt fra loggen: planen antar det i oppdriftssenteret og beholder balansen forut-akter. Kontroller stampen på neste oppdrag.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="124"/>
        <source>CG y was not identified from the log: the plan assumes it at the CB and keeps the side balance. Check roll on the next mission.</source>
        <translation>Tyngdepunkt y ble ikke bestemt fra loggen: planen antar det i oppdriftssenteret og beholder sidebalansen. Kontroller rullen på neste oppdrag.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="125"/>
        <source>UNSAFE: at the %1 point (%2) the vehicle would have %3 net buoyancy, less than the safety margin %4.</source>
        <translation>USIKKERT: i punktet for %1 (%2) ville fartøyet hatt %3 netto oppdrift, mindre enn sikkerhetsmarginen %4.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="126"/>
        <source>UNSAFE: at the %1 point (%2) the vehicle would have %3 net buoyancy, less than the safety margin %4: it would sink if it lost power there.</source>
        <translation>USIKKERT: i punktet for %1 (%2) ville fartøyet hatt %3 netto oppdrift, mindre enn sikkerhetsmarginen %4: det ville synke om det mistet strømmen der.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="127"/>
        <source>Net buoyancy %1 at the operating depth is above the band (%2) because the safety margin (%3) and the less buoyant planned points (%4 less) come first.</source>
        <translation>Netto oppdrift %1 på operasjonsdybden er over båndet (%2) fordi sikkerhetsmarginen (%3) og de planlagte punktene med mindre oppdrift (%4 mindre) går foran.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="128"/>
        <source>The net buoyancy band cannot be reached with this kit while keeping the safety margin: no combination of pieces lands between %1 and %2; the nearest safe one is %3.</source>
        <translation>Båndet for netto oppdrift kan ikke nås med dette vektsettet uten å gi opp sikkerhetsmarginen: ingen kombinasjon av lodd lander mellom %1 og %2; den nærmeste sikre er %3.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="129"/>
        <source>The kit has optional pieces (%1) not used in this plan; allowing them may reach the missed band.</source>
        <translation>Vektsettet har valgfrie lodd (%1) som ikke er brukt i denne planen; tillater du dem, kan båndet som ble bommet på kanskje nås.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="130"/>
        <source>The estimate&apos;s own uncertainty (pitch %1, roll %2) is wider than a tolerance band; the next mission will tell.</source>
        <translation>Estimatets egen usikkerhet (stamp %1, rull %2) er bredere enn et toleransebånd; neste oppdrag vil vise det.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="131"/>
        <source>Classic table (thesis App. E): %1, pitch error %2, roll error %3; it moves one %4 piece per point and mission, whatever the size of the error.</source>
        <translation>Klassisk tabell (oppgavens vedlegg E): %1, stampavvik %2, rullavvik %3; den flytter ett lodd på %4 per punkt og oppdrag, uansett hvor stort avviket er.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="132"/>
        <source>The classic table asks to remove a piece where none is installed, so it changes nothing.</source>
        <translation>Den klassiske tabellen ber om å fjerne et lodd der ingen er montert, så den endrer ingenting.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="133"/>
        <source>The classic table uses the standard kit only.</source>
        <translation>Den klassiske tabellen bruker bare standard vektsett.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="138"/>
        <source>Roll is planned and predicted at cruise (%1 rpm, propeller torque included): the side balance that levels the vehicle there, as the thesis judges roll (§5.3.3).</source>
        <translation>Rull er planlagt og forutsagt i marsjfart (%1 o/min, propellmoment inkludert): sidebalansen som holder fartøyet på rett kjøl der, slik oppgaven bedømmer rull (§5.3.3).</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="140"/>
        <source>%1 is a constant %2 %3 everywhere (all phases, depths and speeds)</source>
        <translation>%1 er konstant %2 %3 overalt (alle faser, dybder og hastigheter)</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="141"/>
        <source>%1 grows %2 %3 per %4 (%5 %3, %6 % of its variance)</source>
        <translation>%1 vokser %2 %3 per %4 (%5 %3, %6 % av variansen)</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="142"/>
        <source>%1 shrinks %2 %3 per %4 (%5 %3, %6 % of its variance)</source>
        <translation>%1 avtar %2 %3 per %4 (%5 %3, %6 % av variansen)</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="143"/>
        <source>%1 grows %2 %3 per %4 %5 %6 %7 (%8 %3, %9 % of its variance)</source>
        <translation>%1 vokser %2 %3 per %4 %5 %6 %7 (%8 %3, %9 % av variansen)</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="144"/>
        <source>%1 shrinks %2 %3 per %4 %5 %6 %7 (%8 %3, %9 % of its variance)</source>
        <translation>%1 avtar %2 %3 per %4 %5 %6 %7 (%8 %3, %9 % av variansen)</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="145"/>
        <source>%1 concentrates at %2 %3 (mean %4 %5 against %6 overall)</source>
        <translation>%1 samler seg ved %2 %3 (middel %4 %5 mot %6 totalt)</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="146"/>
        <source>%1: no factor of the log explains it</source>
        <translation>%1: ingen faktor i loggen forklarer det</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="147"/>
        <source>AUV rigid-body model of the simulator (Fossen form) on smoothed logged states; simulation: replay of the logged commands through the model&apos;s autopilot; ballast state: net buoyancy and CG x/y</source>
        <translation>AUV-stivlegememodellen fra simulatoren (Fossen-form) på glattede loggede tilstander; simulering: de loggede kommandoene spilt av gjennom modellens autopilot; ballasttilstand: netto oppdrift og CG x/y</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="148"/>
        <source>steady glide (Merckelbach et al. 2010) on vertical velocity from the %1; ballast state: net buoyancy at the mean operating state and Cd0</source>
        <translation>stabil gliding (Merckelbach et al. 2010) på vertikal hastighet fra %1; ballasttilstand: netto oppdrift ved middels driftstilstand og Cd0</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="149"/>
        <source>steady glide (Merckelbach et al. 2010) on vertical velocity from the %1; ballast state: net buoyancy at the mean operating state, Cd0 and the lift slope</source>
        <translation>stabil gliding (Merckelbach et al. 2010) på vertikal hastighet fra %1; ballasttilstand: netto oppdrift ved middels driftstilstand, Cd0 og løftestigningstallet</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="253"/>
        <source>bringing the CG back towards the CB fore-aft</source>
        <translation>som flytter tyngdepunktet tilbake mot oppdriftssenteret forut-akter</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="254"/>
        <source>balanced by the other points&apos; fore-aft shares</source>
        <translation>balansert av de andre punktenes andeler forut-akter</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="255"/>
        <source>bringing the CG back towards the CB sideways</source>
        <translation>som flytter tyngdepunktet tilbake mot oppdriftssenteret sideveis</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="256"/>
        <source>balanced by the other points&apos; sideways shares</source>
        <translation>balansert av de andre punktenes andeler sideveis</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="317"/>
        <source>%1: %2 (%3; %4 → %5 of %6).</source>
        <translation>%1: %2 (%3; %4 → %5 av %6).</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="326"/>
        <source>%1 is largest during %2: mean %3 %4</source>
        <translation>%1 er størst under %2: middel %3 %4</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="341"/>
        <source>; independent of %1</source>
        <translation>; uavhengig av %1</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="236"/>
        <location filename="../../ui/wizard/advice_text.cpp" line="304"/>
        <source> and </source>
        <translation> og </translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="240"/>
        <location filename="../../ui/wizard/advice_text.cpp" line="312"/>
        <source>remove %1, then add %2</source>
        <translation>fjern %1, legg så til %2</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="242"/>
        <location filename="../../ui/wizard/advice_text.cpp" line="314"/>
        <source>remove %1</source>
        <translation>fjern %1</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="244"/>
        <location filename="../../ui/wizard/advice_text.cpp" line="316"/>
        <source>add %1</source>
        <translation>legg til %1</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="246"/>
        <source>%1 mm forward</source>
        <translation>%1 mm forover</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="247"/>
        <source>%1 mm aft</source>
        <translation>%1 mm akterover</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="249"/>
        <source>%1 mm to starboard</source>
        <translation>%1 mm mot styrbord</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="250"/>
        <source>%1 mm to port</source>
        <translation>%1 mm mot babord</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="259"/>
        <source>%1: %2 (%3), which lowers the net buoyancy by %4 and moves the CG %5 and %6, %7.</source>
        <translation>%1: %2 (%3), som senker netto oppdrift med %4 og flytter tyngdepunktet %5 og %6, %7.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="260"/>
        <source>%1: %2 (%3), which raises the net buoyancy by %4 and moves the CG %5 and %6, %7.</source>
        <translation>%1: %2 (%3), som øker netto oppdrift med %4 og flytter tyngdepunktet %5 og %6, %7.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="74"/>
        <source>The vehicle stays %1 heavy even with every removable piece out: it needs added buoyancy or a lighter payload.</source>
        <translation>Fartøyet er fortsatt %1 for tungt selv med alle lodd som kan tas ut, ute: det trenger mer oppdrift eller lettere nyttelast.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="75"/>
        <source>The search stopped at its limit: this is the best change found, not a proved optimum.</source>
        <translation>Søket stoppet ved grensen sin: dette er den beste endringen som ble funnet, ikke et bevist optimum.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="76"/>
        <source>The CG is not below the CB after the change: the vehicle would capsize. Check BG and the payload.</source>
        <translation>Tyngdepunktet er ikke under oppdriftssenteret etter endringen: fartøyet ville kantre. Kontroller BG og nyttelasten.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="117"/>
        <source>The thesis mapping leaves the vehicle %1 heavy.</source>
        <translation>Oppgavens fordeling gjør fartøyet %1 for tungt.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="134"/>
        <source>The net buoyancy uncertainty (%1 kg) is too wide for the %2 kg band: add the calibration manoeuvre to the next mission (%3 short leg(s)); with this log alone it would bring the uncertainty to about %4 kg.</source>
        <translation>Usikkerheten i netto oppdrift (%1 kg) er for stor for båndet på %2 kg: legg kalibreringsmanøveren til neste oppdrag (%3 korte etapper); med denne loggen alene ville den bringe usikkerheten ned til omtrent %4 kg.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="135"/>
        <source>This move is also a calibration: flown after it and analysed with the last log as history (the known change of mass and moment between them), the next mission&apos;s survey should tell the net buoyancy to about ±%1 kg and CG x to about ±%2 mm, enough for a second move into the band.</source>
        <translation>Denne flyttingen er også en kalibrering: fløyet etter den og analysert med siste logg som historikk (den kjente endringen i masse og moment mellom dem), bør neste oppdrags kartlegging gi netto oppdrift til omtrent ±%1 kg og CG x til omtrent ±%2 mm, nok til at en ny flytting lander i båndet.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="137"/>
        <source>This move is also a calibration, but flown after it and analysed with the last log as history the next mission&apos;s survey would still leave the net buoyancy at about ±%1 kg (CG x about ±%2 mm), too wide for the band: fly the calibration manoeuvre as well.</source>
        <translation>Denne flyttingen er også en kalibrering, men fløyet etter den og analysert med siste logg som historikk ville neste oppdrags kartlegging fortsatt gi netto oppdrift til omtrent ±%1 kg (CG x omtrent ±%2 mm), for usikkert for båndet: fly kalibreringsmanøveren også.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="272"/>
        <source>The net buoyancy band %1 to %2 cannot be reached with this kit; best %3</source>
        <translation>Båndet for netto oppdrift %1 til %2 kan ikke nås med dette vektsettet; beste er %3</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="274"/>
        <source>The pitch band ±%1 cannot be reached with this kit (at rest); best %2</source>
        <translation>Stampbåndet ±%1 kan ikke nås med dette vektsettet (i ro); beste er %2</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="276"/>
        <source>The roll band ±%1 cannot be reached with this kit while pitch stays in band; best %2</source>
        <translation>Rullbåndet ±%1 kan ikke nås med dette vektsettet mens stampen holdes i båndet; beste er %2</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="278"/>
        <source>The roll band ±%1 cannot be reached with this kit; best %2</source>
        <translation>Rullbåndet ±%1 kan ikke nås med dette vektsettet; beste er %2</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="280"/>
        <source>; flying level at %1 m/s it pitches %2°, inside the band</source>
        <translation>; i planflyging ved %1 m/s stamper det %2°, innenfor båndet</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="281"/>
        <source>; flying level at %1 m/s it pitches %2°, outside the band</source>
        <translation>; i planflyging ved %1 m/s stamper det %2°, utenfor båndet</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="284"/>
        <source>; out of reach whatever the piece sizes: the points&apos; capacities, the installed pieces and the higher priorities limit it</source>
        <translation>; utenfor rekkevidde uansett loddstørrelser: punktenes kapasitet, loddene som er montert og de høyere prioritetene begrenser det</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="287"/>
        <source>; a %1 piece would reach it</source>
        <translation>; et lodd på %1 ville nådd det</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="289"/>
        <source>; no single extra piece size tried (%1) would reach it</source>
        <translation>; ingen enkelt ekstra loddstørrelse som ble prøvd (%1) ville nådd det</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="291"/>
        <source>; no single extra piece size tried (%1) would reach it (some were not searched to the end)</source>
        <translation>; ingen enkelt ekstra loddstørrelse som ble prøvd (%1) ville nådd det (noen ble ikke søkt helt ut)</translation>
    </message>
</context>
<context>
    <name>AdviceWord</name>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="154"/>
        <source>operating</source>
        <translation>operasjonsdybden</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="154"/>
        <source>deepest</source>
        <translation>største dybde</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="155"/>
        <source>surface</source>
        <translation>overflaten</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="155"/>
        <source>transit</source>
        <translation>transitt</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="156"/>
        <source>none</source>
        <translation>ingen</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="158"/>
        <source>depth command steps</source>
        <translation>trinn i dybdekommandoen</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="158"/>
        <source>pitch command steps</source>
        <translation>trinn i stampkommandoen</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="159"/>
        <source>speed changes</source>
        <translation>fartsendringer</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="159"/>
        <source>propeller speed changes</source>
        <translation>endringer i propellturtall</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="162"/>
        <source>vertical-velocity error</source>
        <translation>avvik i vertikal hastighet</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="162"/>
        <source>vertical-force error</source>
        <translation>avvik i vertikal kraft</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="163"/>
        <source>pitch-moment error</source>
        <translation>avvik i stampmoment</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="163"/>
        <source>roll-moment error</source>
        <translation>avvik i rullmoment</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="164"/>
        <source>depth error</source>
        <translation>dybdeavvik</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="164"/>
        <source>pitch error</source>
        <translation>stampavvik</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="165"/>
        <source>roll error</source>
        <translation>rullavvik</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="165"/>
        <source>speed error</source>
        <translation>fartsavvik</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="166"/>
        <source>surge-force error</source>
        <translation>avvik i langskipskraft</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="166"/>
        <source>error</source>
        <translation>avvik</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="167"/>
        <source>pressure</source>
        <translation>trykk</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="167"/>
        <source>temperature</source>
        <translation>temperatur</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="168"/>
        <source>time</source>
        <translation>tid</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="168"/>
        <source>speed</source>
        <translation>fart</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="169"/>
        <source>propeller speed</source>
        <translation>propellturtall</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="169"/>
        <source>pitch</source>
        <translation>stamp</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="170"/>
        <source>time since an actuator change</source>
        <translation>tid siden en ror- eller turtallsendring</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="170"/>
        <source>depth</source>
        <translation>dybde</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="171"/>
        <source>100 dbar</source>
        <translation>100 dbar</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="171"/>
        <source>degC</source>
        <translation>°C</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="172"/>
        <source>hour</source>
        <translation>time</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="172"/>
        <source>0.1 m/s</source>
        <translation>0,1 m/s</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="173"/>
        <source>100 rpm</source>
        <translation>100 o/min</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="173"/>
        <source>10 deg of pitch</source>
        <translation>10° stamp</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="174"/>
        <source>10 s since an actuator change</source>
        <translation>10 s siden en ror- eller turtallsendring</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="175"/>
        <source>below</source>
        <translation>under</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="175"/>
        <source>above</source>
        <translation>over</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="176"/>
        <source>after</source>
        <translation>etter</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="176"/>
        <source>before</source>
        <translation>før</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="177"/>
        <source>within</source>
        <translation>innenfor</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="178"/>
        <source>surfaces</source>
        <translation>overflateopphold</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="178"/>
        <source>dives</source>
        <translation>dykk</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="179"/>
        <source>climbs</source>
        <translation>stigninger</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="179"/>
        <source>levels</source>
        <translation>planflyvninger</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="180"/>
        <source>turns</source>
        <translation>svinger</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="182"/>
        <source>starboard</source>
        <translation>styrbord</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="182"/>
        <source>port</source>
        <translation>babord</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="183"/>
        <source>port to the starboard</source>
        <translation>babord til styrbord</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="183"/>
        <source>starboard to the port</source>
        <translation>styrbord til babord</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="184"/>
        <source>lower to the upper</source>
        <translation>nedre til øvre</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="184"/>
        <source>upper to the lower</source>
        <translation>øvre til nedre</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="185"/>
        <source>lowers</source>
        <translation>senker</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/advice_text.cpp" line="185"/>
        <source>raises</source>
        <translation>hever</translation>
    </message>
</context>
<context>
    <name>ModelWords</name>
    <message>
        <location filename="../../ui/wizard/model_words.cpp" line="17"/>
        <source>hull compressibility</source>
        <translation>skrogets kompressibilitet</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/model_words.cpp" line="18"/>
        <source>hull thermal expansion</source>
        <translation>skrogets varmeutvidelse</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/model_words.cpp" line="19"/>
        <source>propeller torque</source>
        <translation>propellmoment</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/model_words.cpp" line="20"/>
        <source>mass drift</source>
        <translation>massedrift</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/model_words.cpp" line="21"/>
        <source>pitch sensor bias</source>
        <translation>skjevhet i stampsensoren</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/model_words.cpp" line="22"/>
        <source>roll sensor bias</source>
        <translation>skjevhet i rullsensoren</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/model_words.cpp" line="23"/>
        <source>depth sensor offset</source>
        <translation>nullpunktsfeil i dybdesensoren</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/model_words.cpp" line="24"/>
        <source>quadratic pitch damping</source>
        <translation>kvadratisk stampdemping</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/model_words.cpp" line="25"/>
        <source>vertical current</source>
        <translation>vertikal strøm</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/model_words.cpp" line="41"/>
        <source>vertical velocity</source>
        <translation>vertikal hastighet</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/model_words.cpp" line="42"/>
        <source>vertical force</source>
        <translation>vertikal kraft</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/model_words.cpp" line="43"/>
        <source>pitch moment</source>
        <translation>stampmoment</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/model_words.cpp" line="44"/>
        <source>roll moment</source>
        <translation>rullmoment</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/model_words.cpp" line="45"/>
        <source>depth</source>
        <translation>dybde</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/model_words.cpp" line="46"/>
        <source>pitch</source>
        <translation>stamp</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/model_words.cpp" line="47"/>
        <source>roll</source>
        <translation>rull</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/model_words.cpp" line="48"/>
        <source>speed</source>
        <translation>fart</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/model_words.cpp" line="49"/>
        <source>surge force</source>
        <translation>kraft i lengderetningen</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/model_words.cpp" line="61"/>
        <source>ballast state</source>
        <translation>ballasttilstand</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/model_words.cpp" line="62"/>
        <source>the simulator</source>
        <translation>simulatoren</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/model_words.cpp" line="67"/>
        <source>to</source>
        <translation>til</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/model_words.cpp" line="76"/>
        <source>equation error</source>
        <translation>likningsavvik</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/model_words.cpp" line="77"/>
        <source>simulation error</source>
        <translation>simuleringsavvik</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/model_words.cpp" line="78"/>
        <source>term contribution</source>
        <translation>leddets bidrag</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="39"/>
        <source>%1 %2 × %3</source>
        <translation>%1 %2 × %3</translation>
    </message>
</context>
<context>
    <name>auv::ui::AdjustmentPage</name>
    <message>
        <location filename="../../ui/pages/adjustment_page.cpp" line="47"/>
        <source>installed mass</source>
        <translation>montert masse</translation>
    </message>
    <message>
        <location filename="../../ui/pages/adjustment_page.cpp" line="59"/>
        <source>Adjust the ballast</source>
        <translation>Juster ballasten</translation>
    </message>
    <message>
        <location filename="../../ui/pages/adjustment_page.cpp" line="60"/>
        <source>Do the steps, tick each one, then enter what is actually in each point if it differs.</source>
        <translation>Gjør stegene, kryss av hvert av dem, og skriv inn hva som faktisk er i hvert punkt hvis det avviker.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/adjustment_page.cpp" line="67"/>
        <source>Quantity</source>
        <translation>Størrelse</translation>
    </message>
    <message>
        <location filename="../../ui/pages/adjustment_page.cpp" line="67"/>
        <source>Now</source>
        <translation>Nå</translation>
    </message>
    <message>
        <location filename="../../ui/pages/adjustment_page.cpp" line="67"/>
        <source>After (± 1σ)</source>
        <translation>Etter (± 1σ)</translation>
    </message>
    <message>
        <location filename="../../ui/pages/adjustment_page.cpp" line="67"/>
        <source>Band</source>
        <translation>Bånd</translation>
    </message>
    <message>
        <location filename="../../ui/pages/adjustment_page.cpp" line="77"/>
        <source>What the vehicle will do at the operating depth, against the spec bands. Green: inside the band, red: outside.</source>
        <translation>Hva fartøyet vil gjøre på operasjonsdybden, mot kravbåndene. Grønn: innenfor båndet, rød: utenfor.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/adjustment_page.cpp" line="91"/>
        <source>&amp;Steps (tick each when done):</source>
        <translation>&amp;Steg (kryss av hvert når det er gjort):</translation>
    </message>
    <message>
        <location filename="../../ui/pages/adjustment_page.cpp" line="94"/>
        <source>Do the steps in this order: removals first. Space ticks the selected step.</source>
        <translation>Gjør stegene i denne rekkefølgen: det som skal fjernes først. Mellomrom krysser av valgt steg.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/adjustment_page.cpp" line="99"/>
        <source>Actually installed</source>
        <translation>Faktisk montert</translation>
    </message>
    <message>
        <location filename="../../ui/pages/adjustment_page.cpp" line="107"/>
        <source>&amp;Undo</source>
        <translation>&amp;Angre</translation>
    </message>
    <message>
        <location filename="../../ui/pages/adjustment_page.cpp" line="112"/>
        <source>&amp;Redo</source>
        <translation>&amp;Gjør om</translation>
    </message>
    <message>
        <location filename="../../ui/pages/adjustment_page.cpp" line="125"/>
        <source>Undo the last change of an installed mass (Ctrl+Z).</source>
        <translation>Angre siste endring av en montert masse (Ctrl+Z).</translation>
    </message>
    <message>
        <location filename="../../ui/pages/adjustment_page.cpp" line="130"/>
        <source>Redo the change undone last (Ctrl+Shift+Z).</source>
        <translation>Gjør om endringen som sist ble angret (Ctrl+Shift+Z).</translation>
    </message>
    <message>
        <location filename="../../ui/pages/adjustment_page.cpp" line="207"/>
        <source>Kit pieces now in &apos;%1&apos; after the work, in kg. Planned: %2. Arrows step by one %3 piece; Ctrl+Z undoes.</source>
        <translation>Vektbiter i «%1» etter arbeidet, i kg. Planlagt: %2. Piltastene endrer med én %3-bit; Ctrl+Z angrer.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/adjustment_page.cpp" line="240"/>
        <source>Add %1 × %2 at %3</source>
        <translation>Legg til %1 × %2 i %3</translation>
    </message>
    <message>
        <location filename="../../ui/pages/adjustment_page.cpp" line="240"/>
        <source>Remove %1 × %2 at %3</source>
        <translation>Fjern %1 × %2 fra %3</translation>
    </message>
    <message>
        <location filename="../../ui/pages/adjustment_page.cpp" line="253"/>
        <source>Nothing to change: the vehicle stays as it is.</source>
        <translation>Ingenting å endre: fartøyet blir som det er.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/adjustment_page.cpp" line="288"/>
        <source>%1 of %2 done</source>
        <translation>%1 av %2 gjort</translation>
    </message>
    <message>
        <location filename="../../ui/pages/adjustment_page.cpp" line="306"/>
        <source>Net buoyancy</source>
        <translation>Netto oppdrift</translation>
    </message>
    <message>
        <location filename="../../ui/pages/adjustment_page.cpp" line="306"/>
        <source>%1 kg</source>
        <translation>%1 kg</translation>
    </message>
    <message>
        <location filename="../../ui/pages/adjustment_page.cpp" line="307"/>
        <source>%1 ± %2 kg</source>
        <translation>%1 ± %2 kg</translation>
    </message>
    <message>
        <location filename="../../ui/pages/adjustment_page.cpp" line="308"/>
        <source>%1 .. %2 kg</source>
        <translation>%1 .. %2 kg</translation>
    </message>
    <message>
        <location filename="../../ui/pages/adjustment_page.cpp" line="310"/>
        <source>Pitch at rest</source>
        <translation>Stamp i ro</translation>
    </message>
    <message>
        <location filename="../../ui/pages/adjustment_page.cpp" line="320"/>
        <source>Pitch in flight (%1 m/s)</source>
        <translation>Stamp under fart (%1 m/s)</translation>
    </message>
    <message>
        <location filename="../../ui/pages/adjustment_page.cpp" line="383"/>
        <source> Pitch in flight %1° %2.</source>
        <translation> Stamp under fart %1° %2.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/adjustment_page.cpp" line="310"/>
        <location filename="../../ui/pages/adjustment_page.cpp" line="313"/>
        <location filename="../../ui/pages/adjustment_page.cpp" line="321"/>
        <location filename="../../ui/pages/adjustment_page.cpp" line="322"/>
        <source>%1°</source>
        <translation>%1°</translation>
    </message>
    <message>
        <location filename="../../ui/pages/adjustment_page.cpp" line="312"/>
        <location filename="../../ui/pages/adjustment_page.cpp" line="315"/>
        <location filename="../../ui/pages/adjustment_page.cpp" line="323"/>
        <source>±%1°</source>
        <translation>±%1°</translation>
    </message>
    <message>
        <location filename="../../ui/pages/adjustment_page.cpp" line="313"/>
        <source>Roll</source>
        <translation>Rull</translation>
    </message>
    <message>
        <location filename="../../ui/pages/adjustment_page.cpp" line="343"/>
        <source>%1 m %2 kg</source>
        <translation>%1 m %2 kg</translation>
    </message>
    <message>
        <location filename="../../ui/pages/adjustment_page.cpp" line="345"/>
        <source>Safety: net buoyancy stays above the margin %1 kg (%2) at every planned depth: %3.</source>
        <translation>Sikkerhet: netto oppdrift holder seg over marginen %1 kg (%2) på hver planlagte dybde: %3.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/adjustment_page.cpp" line="346"/>
        <source>&lt;span style=&apos;color:#b00020&apos;&gt;Not safe: net buoyancy falls below the margin %1 kg (%2) at a planned depth: %3.&lt;/span&gt;</source>
        <translation>&lt;span style=&apos;color:#b00020&apos;&gt;Ikke sikkert: netto oppdrift faller under marginen %1 kg (%2) på en planlagt dybde: %3.&lt;/span&gt;</translation>
    </message>
    <message>
        <location filename="../../ui/pages/adjustment_page.cpp" line="348"/>
        <source>1.645 σ</source>
        <translation>1,645 σ</translation>
    </message>
    <message>
        <location filename="../../ui/pages/adjustment_page.cpp" line="364"/>
        <source>As planned: the prediction above holds.</source>
        <translation>Som planlagt: prediksjonen over gjelder.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/adjustment_page.cpp" line="382"/>
        <source>.</source>
        <translation>.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/adjustment_page.cpp" line="382"/>
        <source>; NOT safe at every planned depth.</source>
        <translation>; IKKE sikkert på hver planlagte dybde.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/adjustment_page.cpp" line="434"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../../ui/pages/adjustment_page.cpp" line="279"/>
        <source>&lt;b&gt;Calibration manoeuvre&lt;/b&gt; to add to the next mission: %1</source>
        <translation>&lt;b&gt;Kalibreringsmanøver&lt;/b&gt; å legge til neste oppdrag: %1</translation>
    </message>
    <message>
        <location filename="../../ui/pages/adjustment_page.cpp" line="375"/>
        <source>Differs from the plan at %1. As installed: net buoyancy %2 %3, pitch %4 %5, roll %6 %7%8</source>
        <translation>Avviker fra planen i %1. Slik det er montert: netto oppdrift %2 %3, stamp %4 %5, rull %6 %7%8</translation>
    </message>
    <message>
        <location filename="../../ui/pages/adjustment_page.cpp" line="377"/>
        <source> kg</source>
        <translation> kg</translation>
    </message>
    <message>
        <location filename="../../ui/pages/adjustment_page.cpp" line="311"/>
        <location filename="../../ui/pages/adjustment_page.cpp" line="314"/>
        <location filename="../../ui/pages/adjustment_page.cpp" line="378"/>
        <location filename="../../ui/pages/adjustment_page.cpp" line="380"/>
        <source>°</source>
        <translation>°</translation>
    </message>
</context>
<context>
    <name>auv::ui::CalibrationTable</name>
    <message>
        <location filename="../../ui/widgets/calibration_table.cpp" line="27"/>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/calibration_table.cpp" line="45"/>
        <source>Unit: %1</source>
        <translation>Enhet: %1</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/calibration_table.cpp" line="55"/>
        <source>%1 = profile</source>
        <translation>%1 = profil</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/calibration_table.cpp" line="51"/>
        <source>%1 ± %2%3</source>
        <translation>%1 ± %2%3</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/calibration_table.cpp" line="52"/>
        <source>not known</source>
        <translation>ikke kjent</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/calibration_table.cpp" line="54"/>
        <source>not given</source>
        <translation>ikke oppgitt</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/calibration_table.cpp" line="72"/>
        <source>Calibrated constant</source>
        <translation>Kalibrert konstant</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/calibration_table.cpp" line="72"/>
        <source>Value ± σ</source>
        <translation>Verdi ± σ</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/calibration_table.cpp" line="72"/>
        <source>Profile</source>
        <translation>Profil</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/calibration_table.cpp" line="72"/>
        <source>From</source>
        <translation>Fra</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/calibration_table.cpp" line="83"/>
        <source>The vehicle constants fitted together with the ballast state. &quot;This log&quot;: the log narrowed it; &quot;stayed at the prior&quot;: the log could not tell, the profile&apos;s value and its uncertainty stand; &quot;the analysis, held&quot;: the model check kept the same log&apos;s analysis&apos;s value and σ; &quot;profile&apos;s kept&quot;: the log measured it and found no significant change, so the estimate kept the profile&apos;s value.</source>
        <translation>Fartøykonstantene tilpasset sammen med ballasttilstanden. «Denne loggen»: loggen snevret den inn; «ble ved forhåndsverdien»: loggen kunne ikke avgjøre det, og profilens verdi og usikkerhet står; «analysens, holdt»: modellkontrollen beholdt verdien og σ fra analysen av den samme loggen; «profilens beholdt»: loggen målte den og fant ingen vesentlig endring, så estimatet beholdt profilens verdi.</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/calibration_table.cpp" line="95"/>
        <source>Nothing was calibrated: the profile&apos;s constants are used as they are.</source>
        <translation>Ingenting ble kalibrert: profilens konstanter brukes som de er.</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/calibration_table.cpp" line="133"/>
        <source>Heave lift of the hull</source>
        <translation>Skrogets løft i hiv</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/calibration_table.cpp" line="134"/>
        <source>Heave force derivatives</source>
        <translation>Deriverte av hivkraften</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/calibration_table.cpp" line="135"/>
        <location filename="../../ui/widgets/calibration_table.cpp" line="136"/>
        <source>Pitch moment from heave (with the Munk moment)</source>
        <translation>Stampemoment fra hiv (med Munk-momentet)</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/calibration_table.cpp" line="137"/>
        <source>Cross-flow lift and moment</source>
        <translation>Tverrstrømsløft og -moment</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/calibration_table.cpp" line="138"/>
        <source>Cross-flow pitch moment</source>
        <translation>Tverrstrømmens stampemoment</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/calibration_table.cpp" line="139"/>
        <source>Stern-plane effectiveness</source>
        <translation>Virkningen av akterrorene</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/calibration_table.cpp" line="140"/>
        <source>Elevator zero offset</source>
        <translation>Nullpunktsavvik for dybderoret</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/calibration_table.cpp" line="141"/>
        <source>BG (CG below CB)</source>
        <translation>BG (CG under CB)</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/calibration_table.cpp" line="142"/>
        <source>Propeller torque</source>
        <translation>Propellmoment</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/calibration_table.cpp" line="143"/>
        <source>Pitch damping</source>
        <translation>Stampedemping</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/calibration_table.cpp" line="144"/>
        <source>Roll damping</source>
        <translation>Rulledemping</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/calibration_table.cpp" line="145"/>
        <source>Surge drag</source>
        <translation>Motstand i lengderetningen</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/calibration_table.cpp" line="146"/>
        <source>Hull compressibility</source>
        <translation>Skrogets kompressibilitet</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/calibration_table.cpp" line="147"/>
        <source>Hull thermal expansion</source>
        <translation>Skrogets termiske utvidelse</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/calibration_table.cpp" line="148"/>
        <source>Mass drift</source>
        <translation>Masseendring over tid</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/calibration_table.cpp" line="160"/>
        <source>this log</source>
        <translation>denne loggen</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/calibration_table.cpp" line="177"/>
        <source>At the profile&apos;s value (the log could not tell, or agreed with it): %1</source>
        <translation>Ved profilens verdi (loggen kunne ikke avgjøre det, eller var enig med den): %1</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/calibration_table.cpp" line="159"/>
        <source>profile&apos;s kept</source>
        <translation>profilens beholdt</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/calibration_table.cpp" line="158"/>
        <source>the analysis, held</source>
        <translation>analysens, holdt</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/calibration_table.cpp" line="160"/>
        <source>stayed at the prior</source>
        <translation>ble ved forhåndsverdien</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/calibration_table.cpp" line="173"/>
        <source>%1: %2 (profile %3); %4</source>
        <translation>%1: %2 (profil %3); %4</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/calibration_table.cpp" line="191"/>
        <location filename="../../ui/widgets/calibration_table.cpp" line="200"/>
        <source>net buoyancy ± %1 kg</source>
        <translation>netto oppdrift ± %1 kg</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/calibration_table.cpp" line="192"/>
        <location filename="../../ui/widgets/calibration_table.cpp" line="201"/>
        <source>CG x ± %1 mm</source>
        <translation>CG x ± %1 mm</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/calibration_table.cpp" line="193"/>
        <source>Expected afterwards (1 σ): %1</source>
        <translation>Forventet etterpå (1 σ): %1</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/calibration_table.cpp" line="202"/>
        <source>The move is also a calibration: flown after it and analysed with this log as history, the next mission&apos;s survey should give %1 (1 σ).</source>
        <translation>Flyttingen er også en kalibrering: fløyet etter den og analysert med denne loggen som historikk bør neste oppdrags kartlegging gi %1 (1 σ).</translation>
    </message>
</context>
<context>
    <name>auv::ui::ColumnMappingDialog</name>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="41"/>
        <source>&amp;Time *</source>
        <translation>&amp;Tid *</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="42"/>
        <source>&amp;Depth, measured *</source>
        <translation>&amp;Dybde, målt *</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="43"/>
        <source>Depth &amp;command</source>
        <translation>Ønsket d&amp;ybde</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="44"/>
        <source>&amp;Pitch</source>
        <translation>&amp;Stamp</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="45"/>
        <source>Pitch c&amp;ommand</source>
        <translation>Ønsket st&amp;amp</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="46"/>
        <source>&amp;Roll</source>
        <translation>&amp;Rull</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="47"/>
        <source>Speed through &amp;water</source>
        <translation>Fart gjennom &amp;vannet</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="48"/>
        <source>Propeller sp&amp;eed</source>
        <translation>Propellt&amp;urtall</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="49"/>
        <source>E&amp;levator angle</source>
        <translation>Dybderorvin&amp;kel</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="50"/>
        <source>Press&amp;ure (CTD)</source>
        <translation>Trykk (&amp;CTD)</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="51"/>
        <source>Water te&amp;mperature</source>
        <translation>Vanntem&amp;peratur</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="52"/>
        <source>Sali&amp;nity</source>
        <translation>Sa&amp;linitet</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="53"/>
        <source>Buoyancy pump &amp;volume</source>
        <translation>&amp;Oppdriftspumpens volum</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="121"/>
        <source>Map the columns of %1</source>
        <translation>Koble kolonnene i %1</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="124"/>
        <source>Say which column of the file holds each quantity. The first rows are shown below; the choices are pre-filled with what the reader recognised.</source>
        <translation>Angi hvilken kolonne i filen som inneholder hver størrelse. De første radene vises nedenfor; valgene er forhåndsutfylt med det leseren kjente igjen.</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="131"/>
        <source>The first rows of the file, split at the chosen delimiter.</source>
        <translation>De første radene i filen, delt ved valgt skilletegn.</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="136"/>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="145"/>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="153"/>
        <source>recognise</source>
        <translation>gjenkjenn</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="137"/>
        <source>comma ,</source>
        <translation>komma ,</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="138"/>
        <source>semicolon ;</source>
        <translation>semikolon ;</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="139"/>
        <source>tab</source>
        <translation>tabulator</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="140"/>
        <source>blanks</source>
        <translation>mellomrom</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="141"/>
        <source>What separates the columns. &apos;recognise&apos; lets the reader decide from the file.</source>
        <translation>Hva som skiller kolonnene. «gjenkjenn» lar leseren avgjøre ut fra filen.</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="146"/>
        <source>point 1.5</source>
        <translation>punktum 1.5</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="147"/>
        <source>comma 1,5</source>
        <translation>komma 1,5</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="148"/>
        <source>The decimal mark of the numbers (a comma is only possible when the columns are not separated by commas).</source>
        <translation>Desimaltegnet i tallene (komma er bare mulig når kolonnene ikke er skilt med komma).</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="154"/>
        <source>seconds (or the unit)</source>
        <translation>sekunder (eller enheten)</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="155"/>
        <source>seconds since 1970</source>
        <translation>sekunder siden 1970</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="156"/>
        <source>ISO 8601 (2026-05-14T08:12:00Z)</source>
        <translation>ISO 8601 (2026-05-14T08:12:00Z)</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="157"/>
        <source>dd.mm.yyyy hh:mm:ss</source>
        <translation>dd.mm.åååå tt:mm:ss</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="158"/>
        <source>hh:mm:ss (date from a date column)</source>
        <translation>tt:mm:ss (dato fra en datokolonne)</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="160"/>
        <source>How the time column is written.</source>
        <translation>Hvordan tidskolonnen er skrevet.</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="162"/>
        <source> h</source>
        <translation> t</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="163"/>
        <source>The logger clock runs at UTC + this many hours (e.g. 2 for CEST). Leave at &apos;not stated&apos; when the times are UTC or carry their zone.</source>
        <translation>Loggerens klokke går på UTC + så mange timer (f.eks. 2 for sommertid). La stå på «ikke oppgitt» når tidene er UTC eller har sin egen sone.</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="166"/>
        <source>not stated</source>
        <translation>ikke oppgitt</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="169"/>
        <source>Delim&amp;iter:</source>
        <translation>Sk&amp;illetegn:</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="171"/>
        <source>Decimal mar&amp;k:</source>
        <translation>Desi&amp;maltegn:</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="173"/>
        <source>Time &amp;format:</source>
        <translation>Tids&amp;format:</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="184"/>
        <source>Lo&amp;gger clock: UTC +</source>
        <translation>Lo&amp;ggerklokke: UTC +</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="190"/>
        <source>Columns (* = required; depth may instead come from pressure)</source>
        <translation>Kolonner (* = påkrevd; dybden kan i stedet komme fra trykket)</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="198"/>
        <source>&lt;b&gt;Quantity&lt;/b&gt;</source>
        <translation>&lt;b&gt;Størrelse&lt;/b&gt;</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="199"/>
        <source>&lt;b&gt;Column in the file&lt;/b&gt;</source>
        <translation>&lt;b&gt;Kolonne i filen&lt;/b&gt;</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="200"/>
        <source>&lt;b&gt;Unit&lt;/b&gt;</source>
        <translation>&lt;b&gt;Enhet&lt;/b&gt;</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="209"/>
        <source>The column holding this quantity, or &apos;not in this file&apos;.</source>
        <translation>Kolonnen med denne størrelsen, eller «ikke i denne filen».</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="215"/>
        <source>Unit of numeric times: s, ms, min or h. Empty = from the header, else s.</source>
        <translation>Enhet for numeriske tider: s, ms, min eller h. Tom = fra overskriften, ellers s.</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="216"/>
        <source>Unit of the numbers in the file, e.g. m, ft, dbar, deg, rad, m/s, knots, rpm, degC. Empty = from the header, else the format&apos;s unit.</source>
        <translation>Enheten til tallene i filen, f.eks. m, ft, dbar, deg, rad, m/s, knots, rpm, degC. Tom = fra overskriften, ellers formatets enhet.</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="238"/>
        <source>&amp;Save this mapping for %1 (used for its next text logs)</source>
        <translation>Lagr&amp;e koblingen for %1 (brukes for de neste tekstloggene)</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="240"/>
        <source>Keep the mapping so later logs of this vehicle are read the same way without asking.</source>
        <translation>Behold koblingen slik at senere logger fra dette fartøyet leses likt uten å spørre.</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="245"/>
        <source>Read with this m&amp;apping</source>
        <translation>Les med denne ko&amp;blingen</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="247"/>
        <source>Cancel</source>
        <translation>Avbryt</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="339"/>
        <source>(not in this file)</source>
        <translation>(ikke i denne filen)</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="476"/>
        <source>Choose the time column.</source>
        <translation>Velg tidskolonnen.</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="480"/>
        <source>Choose the depth column (or a pressure column below).</source>
        <translation>Velg dybdekolonnen (eller en trykkolonne nedenfor).</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="486"/>
        <source>Already chosen for %1.</source>
        <translation>Allerede valgt for %1.</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/column_mapping_dialog.cpp" line="518"/>
        <source>The first rows cannot be read with this mapping: %1</source>
        <translation>De første radene kan ikke leses med denne koblingen: %1</translation>
    </message>
</context>
<context>
    <name>auv::ui::CraneSideView</name>
    <message>
        <location filename="../../ui/widgets/crane_side_view.cpp" line="16"/>
        <source>Side view, bow to the right: where each crane scale hangs and what it reads.</source>
        <translation>Sett fra siden, baugen til høyre: hvor hver kranvekt henger og hva den viser.</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/crane_side_view.cpp" line="54"/>
        <source>bow ▶</source>
        <translation>baug ▶</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/crane_side_view.cpp" line="59"/>
        <source>CB</source>
        <translation>CB</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/crane_side_view.cpp" line="66"/>
        <source>CG</source>
        <translation>CG</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/crane_side_view.cpp" line="80"/>
        <source>hook: %1 kg</source>
        <translation>krok: %1 kg</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/crane_side_view.cpp" line="89"/>
        <source>FS</source>
        <translation>FS</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/crane_side_view.cpp" line="89"/>
        <source>FP</source>
        <translation>FB</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/crane_side_view.cpp" line="90"/>
        <source>AS</source>
        <translation>AS</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/crane_side_view.cpp" line="90"/>
        <source>AP</source>
        <translation>AB</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/crane_side_view.cpp" line="99"/>
        <location filename="../../ui/widgets/crane_side_view.cpp" line="100"/>
        <source>%1 %2 kg</source>
        <translation>%1 %2 kg</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/crane_side_view.cpp" line="112"/>
        <source>Ropes at x = %1 m (fore) and %2 m (aft); starboard and port scales hang one behind the other.</source>
        <translation>Stropper ved x = %1 m (forut) og %2 m (akter); styrbord- og babordvekten henger bak hverandre.</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/crane_side_view.cpp" line="115"/>
        <source>Enter where the ropes are: the fore rope&apos;s x must be forward of (greater than) the aft rope&apos;s.</source>
        <translation>Angi hvor tauene er: fremre taus x må ligge foran (være større enn) aktre taus.</translation>
    </message>
</context>
<context>
    <name>auv::ui::CraneWeighingPage</name>
    <message>
        <location filename="../../ui/pages/crane_weighing_page.cpp" line="19"/>
        <source>Weighing with crane scales</source>
        <translation>Veiing med kranvekter</translation>
    </message>
    <message>
        <location filename="../../ui/pages/crane_weighing_page.cpp" line="20"/>
        <source>Hang the vehicle from two ropes, fore and aft, with a crane scale at each rope end, and read the hook scale for the total.</source>
        <translation>Heng fartøyet i to stropper, forut og akter, med en kranvekt i hver stroppende, og les av vekten i kroken for totalen.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/crane_weighing_page.cpp" line="22"/>
        <source>Fore / &amp;starboard:</source>
        <translation>Forut / &amp;styrbord:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/crane_weighing_page.cpp" line="22"/>
        <source>Fore / &amp;port:</source>
        <translation>Forut / &amp;babord:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/crane_weighing_page.cpp" line="22"/>
        <source>Aft / s&amp;tarboard:</source>
        <translation>Akter / s&amp;tyrbord:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/crane_weighing_page.cpp" line="23"/>
        <source>Aft / p&amp;ort:</source>
        <translation>Akter / b&amp;abord:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/crane_weighing_page.cpp" line="25"/>
        <source>Scale readings</source>
        <translation>Vektavlesninger</translation>
    </message>
    <message>
        <location filename="../../ui/pages/crane_weighing_page.cpp" line="30"/>
        <source>Reading of the crane scale at this rope end, in kg, with the vehicle hanging still.</source>
        <translation>Avlesning av kranvekten i denne stroppenden, i kg, med fartøyet hengende i ro.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/crane_weighing_page.cpp" line="33"/>
        <source>Reading of the scale on the crane hook (the whole vehicle).</source>
        <translation>Avlesning av vekten i krankroken (hele fartøyet).</translation>
    </message>
    <message>
        <location filename="../../ui/pages/crane_weighing_page.cpp" line="34"/>
        <source>Hoo&amp;k (total):</source>
        <translation>&amp;Krok (total):</translation>
    </message>
    <message>
        <location filename="../../ui/pages/crane_weighing_page.cpp" line="39"/>
        <source>Rope positions</source>
        <translation>Stroppeposisjoner</translation>
    </message>
    <message>
        <location filename="../../ui/pages/crane_weighing_page.cpp" line="42"/>
        <source>x of the fore rope from the vehicle origin, forward positive (measure along the hull).</source>
        <translation>x for fremre stropp fra fartøyets origo, positiv forover (mål langs skroget).</translation>
    </message>
    <message>
        <location filename="../../ui/pages/crane_weighing_page.cpp" line="43"/>
        <source>x of the aft rope from the vehicle origin, forward positive.</source>
        <translation>x for aktre stropp fra fartøyets origo, positiv forover.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/crane_weighing_page.cpp" line="44"/>
        <source>Half the lateral distance between the two ends of one rope.</source>
        <translation>Halve sideavstanden mellom de to endene av en stropp.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/crane_weighing_page.cpp" line="45"/>
        <source>&amp;Fore rope x:</source>
        <translation>&amp;Fremre stropp x:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/crane_weighing_page.cpp" line="46"/>
        <source>&amp;Aft rope x:</source>
        <translation>&amp;Aktre stropp x:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/crane_weighing_page.cpp" line="47"/>
        <source>Rope end &amp;y (±):</source>
        <translation>Stroppende &amp;y (±):</translation>
    </message>
    <message>
        <location filename="../../ui/pages/crane_weighing_page.cpp" line="49"/>
        <source>Adjustment weight installed now</source>
        <translation>Trimvekt montert nå</translation>
    </message>
    <message>
        <location filename="../../ui/pages/crane_weighing_page.cpp" line="53"/>
        <source>Kit pieces already in this point, in kg.</source>
        <translation>Vektlodd som allerede sitter i dette punktet, i kg.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/crane_weighing_page.cpp" line="126"/>
        <source>Kit pieces already in &apos;%1&apos;, in kg.</source>
        <translation>Vektlodd som allerede sitter i «%1», i kg.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/crane_weighing_page.cpp" line="143"/>
        <source>Parts add up to %1 kg (%2 kg against the hook)</source>
        <translation>Delene summerer til %1 kg (%2 kg mot kroken)</translation>
    </message>
    <message>
        <location filename="../../ui/pages/crane_weighing_page.cpp" line="148"/>
        <source>: more than %1 kg, check the readings</source>
        <translation>: mer enn %1 kg, kontroller avlesningene</translation>
    </message>
    <message>
        <location filename="../../ui/pages/crane_weighing_page.cpp" line="151"/>
        <source>: re-read the scales</source>
        <translation>: les av vektene på nytt</translation>
    </message>
</context>
<context>
    <name>auv::ui::DeviationPlotsPage</name>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="65"/>
        <location filename="../../ui/widgets/segment_table.cpp" line="41"/>
        <source>Depth [m]</source>
        <translation>Dybde [m]</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="65"/>
        <location filename="../../ui/widgets/segment_table.cpp" line="41"/>
        <source>Pitch [°]</source>
        <translation>Stamp [°]</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="65"/>
        <location filename="../../ui/widgets/segment_table.cpp" line="41"/>
        <source>Roll [°]</source>
        <translation>Rull [°]</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="99"/>
        <source>measured</source>
        <translation>målt</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="99"/>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="322"/>
        <source>commanded</source>
        <translation>kommandert</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="113"/>
        <source>time since start [min]</source>
        <translation>tid siden start [min]</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="151"/>
        <source>&amp;Whole log</source>
        <translation>Hele &amp;loggen</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="151"/>
        <source>Show the whole log in all three charts.</source>
        <translation>Vis hele loggen i alle tre diagrammene.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="229"/>
        <source>commanded depth</source>
        <translation>kommandert dybde</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="230"/>
        <source>commanded pitch</source>
        <translation>kommandert stamp</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="254"/>
        <source>Preparing the plots of %1 rows…</source>
        <translation>Forbereder plottene av %1 rader…</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="269"/>
        <source>Net buoyancy: being computed…</source>
        <translation>Netto oppdrift: beregnes…</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="288"/>
        <source>Analysing the log: steady segments, depth, pitch and roll errors, net buoyancy and centre of gravity…</source>
        <translation>Analyserer loggen: stabile segmenter, dybde-, stamp- og rullavvik, netto oppdrift og tyngdepunkt…</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="324"/>
        <source>not in this log: %1</source>
        <translation>ikke i denne loggen: %1</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="334"/>
        <source>%1: %2 samples in the three charts over %3 min.</source>
        <translation>%1: %2 målepunkter i de tre diagrammene over %3 min.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="349"/>
        <source>The next page&apos;s model check fits the whole log, which may tell the net buoyancy where the steady flight cannot.</source>
        <translation>Modellsjekken på neste side tilpasser hele loggen, og kan kanskje gi netto oppdrift der den stødige flyvningen ikke kan.</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/analysis_summary.cpp" line="27"/>
        <source>n/a</source>
        <translation>i.t.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="62"/>
        <source>Analysis: depth, pitch and roll as flown</source>
        <translation>Analyse: dybde, stamp og rull slik fartøyet gikk</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="63"/>
        <source>Shaded: the steady segments the analysis used. Wheel or +/-: zoom; drag or arrows: move; double-click: whole log.</source>
        <translation>Skyggelagt: de stabile segmentene analysen brukte. Hjul eller +/-: zoom; dra eller piltaster: flytt; dobbeltklikk: hele loggen.</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/segment_table.cpp" line="41"/>
        <source>#</source>
        <translation>#</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/segment_table.cpp" line="41"/>
        <source>min</source>
        <translation>min</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/segment_table.cpp" line="62"/>
        <source>Each steady segment the analysis used (time in minutes): mean error ± its 95 % interval (depth: commanded − measured; pitch: measured − commanded; roll: as measured). A dive or climb (the steady middle of a depth change) shows its mean pitch instead. Click a row to zoom to it.</source>
        <translation>Hvert stabile segment analysen brukte (tid i minutter): middelavvik ± 95 %-intervallet (dybde: ønsket − målt; stamp: målt − ønsket; rull: som målt). Et dykk eller en stigning (den stødige midten av en dybdeendring) viser i stedet sin middelstamp. Klikk på en rad for å zoome til den.</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/segment_table.cpp" line="81"/>
        <source>dive/climb</source>
        <translation>dykk/stigning</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/segment_table.cpp" line="81"/>
        <source>left out</source>
        <translation>utelatt</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/segment_table.cpp" line="89"/>
        <source>A dive or climb left out of the calibration: the other legs&apos; balance does not explain it.</source>
        <translation>Et dykk eller en stigning utelatt fra kalibreringen: balansen fra de andre etappene forklarer det ikke.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="141"/>
        <source>Steady &amp;segments used</source>
        <translation>Brukte stabile &amp;segmenter</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="152"/>
        <source>Export &amp;PNG…</source>
        <translation>Eksporter &amp;PNG…</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="152"/>
        <source>Save the three charts as they are shown as a PNG image.</source>
        <translation>Lagre de tre diagrammene slik de vises, som PNG-bilde.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="153"/>
        <source>Export &amp;CSV…</source>
        <translation>Eksporter &amp;CSV…</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="154"/>
        <source>Save every logged sample of the plotted channels within the visible time window as a mission-log CSV (not the thinned-out points drawn).</source>
        <translation>Lagre alle loggede verdier for de viste kanalene i det synlige tidsvinduet som misjonslogg-CSV (ikke de uttynnede punktene som tegnes).</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/analysis_summary.cpp" line="81"/>
        <source>&lt;b&gt;No analysis&lt;/b&gt;: %1</source>
        <translation>&lt;b&gt;Ingen analyse&lt;/b&gt;: %1</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/analysis_summary.cpp" line="102"/>
        <source>Net buoyancy: &lt;b&gt;%1&lt;/b&gt;</source>
        <translation>Netto oppdrift: &lt;b&gt;%1&lt;/b&gt;</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="355"/>
        <location filename="../../ui/widgets/analysis_summary.cpp" line="102"/>
        <source> kg</source>
        <translation> kg</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/analysis_summary.cpp" line="105"/>
        <source>(too light, 1 σ)</source>
        <translation>(for lett, 1 σ)</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/analysis_summary.cpp" line="105"/>
        <source>(too heavy, 1 σ)</source>
        <translation>(for tung, 1 σ)</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/analysis_summary.cpp" line="105"/>
        <source>(neutral, 1 σ)</source>
        <translation>(nøytral, 1 σ)</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/analysis_summary.cpp" line="108"/>
        <source>; add %1 for neutral at %2 kg/m³</source>
        <translation>; legg til %1 for nøytral ved %2 kg/m³</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/analysis_summary.cpp" line="109"/>
        <source> g</source>
        <translation> g</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/analysis_summary.cpp" line="115"/>
        <source>CG − CB: x &lt;b&gt;%1&lt;/b&gt;, y &lt;b&gt;%2&lt;/b&gt;</source>
        <translation>CG − CB: x &lt;b&gt;%1&lt;/b&gt;, y &lt;b&gt;%2&lt;/b&gt;</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/analysis_summary.cpp" line="116"/>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/analysis_summary.cpp" line="117"/>
        <source>Errors (95 %): depth %1 · pitch %2 · roll %3</source>
        <translation>Avvik (95 %): dybde %1 · stamp %2 · rull %3</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="381"/>
        <location filename="../../ui/widgets/analysis_summary.cpp" line="118"/>
        <location filename="../../ui/widgets/analysis_summary.cpp" line="121"/>
        <source> m</source>
        <translation> m</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="381"/>
        <location filename="../../ui/widgets/analysis_summary.cpp" line="118"/>
        <location filename="../../ui/widgets/analysis_summary.cpp" line="119"/>
        <source>°</source>
        <translation>°</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/analysis_summary.cpp" line="120"/>
        <source>Water at %1: %2 · %3 · %4 (95 %)</source>
        <translation>Vann ved %1: %2 · %3 · %4 (95 %)</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/analysis_summary.cpp" line="121"/>
        <source> °C</source>
        <translation> °C</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/analysis_summary.cpp" line="122"/>
        <source> PSU</source>
        <translation> PSU</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/analysis_summary.cpp" line="123"/>
        <source> kg/m³</source>
        <translation> kg/m³</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/analysis_summary.cpp" line="127"/>
        <source>Net buoyancy</source>
        <translation>Netto oppdrift</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/analysis_summary.cpp" line="127"/>
        <source>CG x</source>
        <translation>CG x</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/analysis_summary.cpp" line="127"/>
        <source>CG y</source>
        <translation>CG y</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/analysis_summary.cpp" line="129"/>
        <source>&lt;b&gt;%1&lt;/b&gt;: %2</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;: %2</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/analysis_summary.cpp" line="130"/>
        <source>Pitch error: %1</source>
        <translation>Stampavvik: %1</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/segment_table.cpp" line="60"/>
        <source>Each steady glide the analysis used (time in minutes): its mean depth and pitch, and the roll ± its 95 % interval. Click a row to zoom to it.</source>
        <translation>Hvert stabile glid analysen brukte (tid i minutter): middeldybde og -stamp, og rull ± 95 %-intervallet. Klikk på en rad for å zoome til den.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="371"/>
        <source>Point at a chart to read the time and the values there.</source>
        <translation>Pek på et diagram for å lese av tiden og verdiene der.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="380"/>
        <source>depth</source>
        <translation>dybde</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="380"/>
        <source>pitch</source>
        <translation>stamp</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="380"/>
        <source>roll</source>
        <translation>rull</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="385"/>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="385"/>
        <source>%1 %2 (command %3)</source>
        <translation>%1 %2 (ønsket %3)</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="387"/>
        <source>&lt;b&gt;%1 min&lt;/b&gt;: %2</source>
        <translation>&lt;b&gt;%1 min&lt;/b&gt;: %2</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="507"/>
        <source>Could not write %1: check the folder and its permissions.</source>
        <translation>Kunne ikke skrive %1: sjekk mappen og tilgangen til den.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="524"/>
        <source>Not exported: %1</source>
        <translation>Ikke eksportert: %1</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="530"/>
        <source>Export the charts</source>
        <translation>Eksporter diagrammene</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="530"/>
        <source>PNG images (*.png)</source>
        <translation>PNG-bilder (*.png)</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="536"/>
        <source>Export the plotted data</source>
        <translation>Eksporter de viste dataene</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="536"/>
        <source>CSV files (*.csv)</source>
        <translation>CSV-filer (*.csv)</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/analysis_summary.cpp" line="113"/>
        <source>CG − CB: &lt;b&gt;%1&lt;/b&gt; (see the notes)</source>
        <translation>CG − CB: &lt;b&gt;%1&lt;/b&gt; (se merknadene)</translation>
    </message>
    <message>
        <location filename="../../ui/pages/deviation_plots_page.cpp" line="354"/>
        <source>This log&apos;s analysis alone: net buoyancy %1.</source>
        <translation>Analysen av denne loggen alene: netto oppdrift %1.</translation>
    </message>
</context>
<context>
    <name>auv::ui::EstimateText</name>
    <message>
        <location filename="../../ui/widgets/estimate_text.cpp" line="9"/>
        <source>not known</source>
        <translation>ikke kjent</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/estimate_text.cpp" line="18"/>
        <source>%1 ± %2%3</source>
        <translation>%1 ± %2%3</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/estimate_text.cpp" line="38"/>
        <source>The plan uses the estimate with the model-check terms you accepted.</source>
        <translation>Planen bruker estimatet med modellsjekk-leddene du godtok.</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/estimate_text.cpp" line="40"/>
        <source>The plan uses the model check&apos;s fit of the whole log: the steady flight alone did not identify the ballast state.</source>
        <translation>Planen bruker modellsjekkens tilpasning av hele loggen: den stødige flyvningen alene identifiserte ikke ballasttilstanden.</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/estimate_text.cpp" line="43"/>
        <source>The plan uses the estimate calibrated from this log and the configuration&apos;s earlier mission (the weight change between them is known).</source>
        <translation>Planen bruker estimatet kalibrert fra denne loggen og det tidligere oppdraget med konfigurasjonen (vektendringen mellom dem er kjent).</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/estimate_text.cpp" line="48"/>
        <source>The plan uses the estimate calibrated from this log.</source>
        <translation>Planen bruker estimatet kalibrert fra denne loggen.</translation>
    </message>
</context>
<context>
    <name>auv::ui::FirstMissionResultPage</name>
    <message>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="40"/>
        <source>add</source>
        <translation>legg til</translation>
    </message>
    <message>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="40"/>
        <source>remove</source>
        <translation>fjern</translation>
    </message>
    <message>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="44"/>
        <source>no change</source>
        <translation>ingen endring</translation>
    </message>
    <message>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="52"/>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="137"/>
        <source>Ballast change before the first mission</source>
        <translation>Ballastendring før første oppdrag</translation>
    </message>
    <message>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="64"/>
        <source>Point</source>
        <translation>Punkt</translation>
    </message>
    <message>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="64"/>
        <source>Change</source>
        <translation>Endring</translation>
    </message>
    <message>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="64"/>
        <source>Pieces</source>
        <translation>Lodd</translation>
    </message>
    <message>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="70"/>
        <source>Installed now, after the work (what the next mission flies with)</source>
        <translation>Montert nå, etter arbeidet (det neste oppdrag flyr med)</translation>
    </message>
    <message>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="74"/>
        <source>Export work &amp;order (PDF)…</source>
        <translation>Eksporter &amp;arbeidsordre (PDF)…</translation>
    </message>
    <message>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="116"/>
        <source>Work order written to %1</source>
        <translation>Arbeidsordre skrevet til %1</translation>
    </message>
    <message>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="116"/>
        <source>Not exported: %1</source>
        <translation>Ikke eksportert: %1</translation>
    </message>
    <message>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="124"/>
        <source>Export the work order</source>
        <translation>Eksporter arbeidsordren</translation>
    </message>
    <message>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="125"/>
        <source>PDF files (*.pdf)</source>
        <translation>PDF-filer (*.pdf)</translation>
    </message>
    <message>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="137"/>
        <source>Ballast change after the tank weighing</source>
        <translation>Ballastendring etter tankveiingen</translation>
    </message>
    <message>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="145"/>
        <source>Cannot compute: %1</source>
        <translation>Kan ikke beregne: %1</translation>
    </message>
    <message>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="154"/>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="187"/>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="191"/>
        <source>%1 g</source>
        <translation>%1 g</translation>
    </message>
    <message>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="155"/>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="188"/>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="192"/>
        <source>%1 kg</source>
        <translation>%1 kg</translation>
    </message>
    <message>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="156"/>
        <source>neutral</source>
        <translation>nøytral</translation>
    </message>
    <message>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="157"/>
        <source>too light</source>
        <translation>for lett</translation>
    </message>
    <message>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="158"/>
        <source>too heavy</source>
        <translation>for tung</translation>
    </message>
    <message>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="159"/>
        <source>Weighed %1 kg; buoyancy %2 kg in %3 kg/m³ water → net buoyancy %4 (%5). CG − CB: x %6 mm, y %7 mm; static pitch %8°, roll %9°.</source>
        <translation>Veid %1 kg; oppdrift %2 kg i %3 kg/m³ vann → netto oppdrift %4 (%5). CG − CB: x %6 mm, y %7 mm; statisk stamp %8°, rull %9°.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="185"/>
        <source>After the change: net buoyancy %1 %2 (band %3..%4), pitch %5° %6 (±%7), roll %8° %9 (±%10).</source>
        <translation>Etter endringen: netto oppdrift %1 %2 (bånd %3..%4), stamp %5° %6 (±%7), rull %8° %9 (±%10).</translation>
    </message>
    <message>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="200"/>
        <source>⚠ %1</source>
        <translation>⚠ %1</translation>
    </message>
    <message>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="221"/>
        <source>g</source>
        <translation>g</translation>
    </message>
    <message>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="221"/>
        <source>kg</source>
        <translation>kg</translation>
    </message>
    <message>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="222"/>
        <source>What is in &apos;%1&apos; now that the work is done (the recommended result is filled in; change it if you installed something else).</source>
        <translation>Det som er i «%1» nå som arbeidet er gjort (det anbefalte resultatet er fylt inn; endre det hvis du monterte noe annet).</translation>
    </message>
    <message>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="254"/>
        <source>Not saved: %1</source>
        <translation>Ikke lagret: %1</translation>
    </message>
    <message>
        <location filename="../../ui/pages/first_mission_result_page.cpp" line="257"/>
        <source>Saved configuration %1: weighing, water, recommendation and installed state.</source>
        <translation>Lagret konfigurasjon %1: veiing, vann, anbefaling og montert tilstand.</translation>
    </message>
</context>
<context>
    <name>auv::ui::GliderBallastMap</name>
    <message>
        <location filename="../../ui/widgets/glider_ballast_map.cpp" line="63"/>
        <source>Side view (bow to the right, keel down)</source>
        <translation>Sett fra siden (baugen til høyre, kjølen ned)</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/glider_ballast_map.cpp" line="64"/>
        <source>Top view (bow to the right, starboard down)</source>
        <translation>Sett ovenfra (baugen til høyre, styrbord ned)</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/glider_ballast_map.cpp" line="151"/>
        <source>$C_VBD %1 → %2</source>
        <translation>$C_VBD %1 → %2</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/glider_ballast_map.cpp" line="155"/>
        <source>, $C_PITCH %1 → %2</source>
        <translation>, $C_PITCH %1 → %2</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/glider_ballast_map.cpp" line="157"/>
        <source>The log does not tell where the grams go on this glider (see the notes).</source>
        <translation>Loggen sier ikke hvor grammene skal på denne glideren (se merknadene).</translation>
    </message>
</context>
<context>
    <name>auv::ui::GliderBallastPage</name>
    <message>
        <location filename="../../ui/pages/glider_ballast_page.cpp" line="32"/>
        <source>Glider: where the grams go</source>
        <translation>Glider: hvor grammene skal</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_ballast_page.cpp" line="33"/>
        <source>What to change on the glider for the next deployment&apos;s water. Finish saves the mission to the history.</source>
        <translation>Hva som skal endres på glideren for vannet ved neste utsetting. Fullfør lagrer oppdraget i historikken.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_ballast_page.cpp" line="49"/>
        <source>Export work &amp;order (PDF)…</source>
        <translation>Eksporter &amp;arbeidsordre (PDF)…</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_ballast_page.cpp" line="52"/>
        <source>One A4 page: the glider, the target water, the grams per place, the map and a signature line.</source>
        <translation>Én A4-side: glideren, målvannet, gram per sted, kartet og en signaturlinje.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_ballast_page.cpp" line="55"/>
        <source>Export the work order</source>
        <translation>Eksporter arbeidsordren</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_ballast_page.cpp" line="55"/>
        <source>PDF files (*.pdf)</source>
        <translation>PDF-filer (*.pdf)</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_ballast_page.cpp" line="90"/>
        <source>Cannot tell: %1</source>
        <translation>Kan ikke si: %1</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_ballast_page.cpp" line="91"/>
        <source>Note: %1</source>
        <translation>Merk: %1</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_ballast_page.cpp" line="116"/>
        <source>Not saved: %1</source>
        <translation>Ikke lagret: %1</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_ballast_page.cpp" line="119"/>
        <source>Saved configuration %1: the mission log, its analysis and the glider&apos;s ballast answer.</source>
        <translation>Lagret konfigurasjon %1: oppdragsloggen, analysen og gliderens ballastsvar.</translation>
    </message>
</context>
<context>
    <name>auv::ui::GliderInstructions</name>
    <message>
        <location filename="../../ui/wizard/glider_work_order.cpp" line="43"/>
        <source>%1: add %2 g of lead shot (holds at most %3 g).</source>
        <translation>%1: legg i %2 g blyhagl (rommer høyst %3 g).</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/glider_work_order.cpp" line="44"/>
        <source>%1: take out %2 g of lead shot (holds at most %3 g).</source>
        <translation>%1: ta ut %2 g blyhagl (rommer høyst %3 g).</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/glider_work_order.cpp" line="49"/>
        <source>Bow bottles %1 g, aft bottles %2 g: %3 g in all, in %4 g steps.</source>
        <translation>Baugflasker %1 g, akterflasker %2 g: %3 g i alt, i trinn på %4 g.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/glider_work_order.cpp" line="56"/>
        <source>Roll %1° at zero roll command: no wing-rail change.</source>
        <translation>Rull %1° ved null rullkommando: ingen endring på vingeskinnene.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/glider_work_order.cpp" line="57"/>
        <source>Roll %1° at zero roll command: move %2 g from the %3 (included above).</source>
        <translation>Rull %1° ved null rullkommando: flytt %2 g fra %3 (med ovenfor).</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/glider_work_order.cpp" line="61"/>
        <source>starboard wing rail to the port wing rail</source>
        <translation>styrbord vingeskinne til babord vingeskinne</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/glider_work_order.cpp" line="62"/>
        <source>port wing rail to the starboard wing rail</source>
        <translation>babord vingeskinne til styrbord vingeskinne</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/glider_work_order.cpp" line="66"/>
        <source>Pitch: level flight at pump zero needs the battery at %1 mm (centre of travel %2 mm); the bow/aft split above brings it back to the centre.</source>
        <translation>Stamp: plan flukt med pumpen på null krever batteriet på %1 mm (midt i vandringen %2 mm); fordelingen baug/akter ovenfor bringer det tilbake til midten.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/glider_work_order.cpp" line="76"/>
        <source>Lead: no change (the VBD takes it).</source>
        <translation>Bly: ingen endring (VBD-en tar det).</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/glider_work_order.cpp" line="77"/>
        <source>Lead: add %1 g (%2 cm³ of lead).</source>
        <translation>Bly: legg til %1 g (%2 cm³ bly).</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/glider_work_order.cpp" line="78"/>
        <source>Lead: take off %1 g (%2 cm³ of lead).</source>
        <translation>Bly: ta av %1 g (%2 cm³ bly).</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/glider_work_order.cpp" line="79"/>
        <source>Set $C_VBD from %1 to %2 (VBD %3 cm³).</source>
        <translation>Sett $C_VBD fra %1 til %2 (VBD %3 cm³).</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/glider_work_order.cpp" line="87"/>
        <source>Set $C_PITCH from %1 to %2 (pitch mass for level flight at %3 mm).</source>
        <translation>Sett $C_PITCH fra %1 til %2 (stampmasse for plan flukt på %3 mm).</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/glider_work_order.cpp" line="94"/>
        <source>Keep $C_PITCH at %1: the log&apos;s pitch trim gives %2, outside PITCH_MIN .. PITCH_MAX (%3 .. %4); check the pitch trim on a test dive.</source>
        <translation>Behold $C_PITCH på %1: loggens stamptrim gir %2, utenfor PITCH_MIN .. PITCH_MAX (%3 .. %4); sjekk stamptrimmen på et prøvedykk.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/glider_work_order.cpp" line="102"/>
        <source>Basis: %1.</source>
        <translation>Grunnlag: %1.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/glider_work_order.cpp" line="112"/>
        <source>%1 ± %2 g</source>
        <translation>%1 ± %2 g</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/glider_work_order.cpp" line="112"/>
        <location filename="../../ui/wizard/glider_work_order.cpp" line="157"/>
        <location filename="../../ui/wizard/glider_work_order.cpp" line="158"/>
        <source>%1 g</source>
        <translation>%1 g</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/glider_work_order.cpp" line="113"/>
        <source>Mass to add %1 for neutral with the pump at zero in %2 kg/m³ water at %3 dbar, %4 °C.</source>
        <translation>Masse å legge til %1 for nøytral med pumpen på null i vann på %2 kg/m³ ved %3 dbar, %4 °C.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/glider_work_order.cpp" line="118"/>
        <source>Target water: %1.</source>
        <translation>Målvann: %1.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/glider_work_order.cpp" line="125"/>
        <source>Change the glider&apos;s mass by %1 g at its ballast places so that it stays level.</source>
        <translation>Endre gliderens masse med %1 g på ballaststedene slik at den holder seg plan.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/glider_work_order.cpp" line="127"/>
        <source>Linear battery for level flight at pump zero: %1 mm.</source>
        <translation>Lineært batteri for plan flukt med pumpen på null: %1 mm.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/glider_work_order.cpp" line="144"/>
        <source>From the log: %1</source>
        <translation>Fra loggen: %1</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/glider_work_order.cpp" line="148"/>
        <source>Place</source>
        <translation>Sted</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/glider_work_order.cpp" line="148"/>
        <source>Change</source>
        <translation>Endring</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/glider_work_order.cpp" line="148"/>
        <source>Pieces</source>
        <translation>Stykker</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/glider_work_order.cpp" line="148"/>
        <source>Holds at most</source>
        <translation>Rommer høyst</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/glider_work_order.cpp" line="148"/>
        <source>Note</source>
        <translation>Merknad</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/glider_work_order.cpp" line="155"/>
        <source>%1 × 1 g lead shot</source>
        <translation>%1 × 1 g blyhagl</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/glider_work_order.cpp" line="156"/>
        <source>%1 g lead</source>
        <translation>%1 g bly</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/glider_work_order.cpp" line="161"/>
        <source>Neutral with the pump at zero in the water above, within ± %1 g (1 σ).</source>
        <translation>Nøytral med pumpen på null i vannet ovenfor, innenfor ± %1 g (1 σ).</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/glider_work_order.cpp" line="162"/>
        <source>Neutral with the pump at zero in the water above.</source>
        <translation>Nøytral med pumpen på null i vannet ovenfor.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/glider_work_order.cpp" line="164"/>
        <source>Cannot tell: %1</source>
        <translation>Kan ikke si: %1</translation>
    </message>
</context>
<context>
    <name>auv::ui::GliderPreMissionPage</name>
    <message>
        <location filename="../../ui/pages/glider_pre_mission_page.cpp" line="29"/>
        <source>%1 ± %2 g</source>
        <translation>%1 ± %2 g</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_pre_mission_page.cpp" line="29"/>
        <source>%1 g</source>
        <translation>%1 g</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_pre_mission_page.cpp" line="39"/>
        <source>Glider: the next deployment&apos;s water</source>
        <translation>Glider: vannet ved neste utsetting</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_pre_mission_page.cpp" line="40"/>
        <source>What the log showed, and the water where the glider must be neutral with its pump at zero.</source>
        <translation>Hva loggen viste, og vannet der glideren skal være nøytral med pumpen på null.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_pre_mission_page.cpp" line="42"/>
        <source>What the log showed</source>
        <translation>Hva loggen viste</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_pre_mission_page.cpp" line="57"/>
        <source>Target water</source>
        <translation>Målvann</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_pre_mission_page.cpp" line="58"/>
        <source>The &amp;log&apos;s own water at its deepest yo</source>
        <translation>&amp;Loggens eget vann i det dypeste yo-et</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_pre_mission_page.cpp" line="60"/>
        <source>Neutral where the recorded mission went deepest: its CTD&apos;s temperature and salinity there.</source>
        <translation>Nøytral der det loggede oppdraget gikk dypest: CTD-ens temperatur og saltholdighet der.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_pre_mission_page.cpp" line="61"/>
        <source>A densit&amp;y</source>
        <translation>En &amp;tetthet</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_pre_mission_page.cpp" line="63"/>
        <source>The in-situ density of the next deployment&apos;s water (pressure and temperature from the log&apos;s deepest water).</source>
        <translation>In situ-tettheten til vannet ved neste utsetting (trykk og temperatur fra loggens dypeste vann).</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_pre_mission_page.cpp" line="64"/>
        <source>&amp;Pressure and temperature</source>
        <translation>Try&amp;kk og temperatur</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_pre_mission_page.cpp" line="66"/>
        <source>Pressure and temperature of the next deployment&apos;s water; with a salinity the density follows from EOS-80, else the log&apos;s salinity is used.</source>
        <translation>Trykk og temperatur i vannet ved neste utsetting; med saltholdighet følger tettheten av EOS-80, ellers brukes loggens saltholdighet.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_pre_mission_page.cpp" line="68"/>
        <source>&amp;A depth in the log&apos;s CTD profile</source>
        <translation>Et &amp;dyp i loggens CTD-profil</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_pre_mission_page.cpp" line="70"/>
        <source>Temperature, salinity and pressure at this depth as the log&apos;s own CTD measured them.</source>
        <translation>Temperatur, saltholdighet og trykk på dette dypet slik loggens egen CTD målte dem.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_pre_mission_page.cpp" line="79"/>
        <source>In-situ density of the target water, kg/m³ (990 .. 1080).</source>
        <translation>In situ-tetthet i målvannet, kg/m³ (990 .. 1080).</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_pre_mission_page.cpp" line="80"/>
        <source>Pressure where the glider must be neutral, dbar.</source>
        <translation>Trykket der glideren skal være nøytral, dbar.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_pre_mission_page.cpp" line="81"/>
        <source>Water temperature there, °C.</source>
        <translation>Vanntemperaturen der, °C.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_pre_mission_page.cpp" line="83"/>
        <source>Practical salinity there; leave it at &apos;not given&apos; to use the log&apos;s own salinity.</source>
        <translation>Praktisk saltholdighet der; la den stå på «ikke oppgitt» for å bruke loggens egen saltholdighet.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_pre_mission_page.cpp" line="84"/>
        <source>not given</source>
        <translation>ikke oppgitt</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_pre_mission_page.cpp" line="85"/>
        <source>A depth the log reached: its CTD there gives T, S and p.</source>
        <translation>Et dyp loggen nådde: CTD-en der gir T, S og p.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_pre_mission_page.cpp" line="95"/>
        <source>&amp;Density:</source>
        <translation>T&amp;etthet:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_pre_mission_page.cpp" line="97"/>
        <source>P&amp;ressure:</source>
        <translation>T&amp;rykk:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_pre_mission_page.cpp" line="98"/>
        <source>&amp;Temperature:</source>
        <translation>&amp;Temperatur:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_pre_mission_page.cpp" line="99"/>
        <source>&amp;Salinity:</source>
        <translation>&amp;Saltholdighet:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_pre_mission_page.cpp" line="101"/>
        <source>D&amp;epth:</source>
        <translation>D&amp;yp:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_pre_mission_page.cpp" line="214"/>
        <source>No analysis: go back and import the mission&apos;s log.</source>
        <translation>Ingen analyse: gå tilbake og importer oppdragets logg.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_pre_mission_page.cpp" line="226"/>
        <source>The analysis (steady-glide fit): add &lt;b&gt;%1&lt;/b&gt; at the log&apos;s own deepest water.</source>
        <translation>Analysen (tilpasning av jevn glidning): legg til &lt;b&gt;%1&lt;/b&gt; i loggens eget dypeste vann.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_pre_mission_page.cpp" line="230"/>
        <source>The model check, fitted jointly with its terms: add &lt;b&gt;%1&lt;/b&gt;.</source>
        <translation>Modellsjekken, tilpasset sammen med leddene sine: legg til &lt;b&gt;%1&lt;/b&gt;.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_pre_mission_page.cpp" line="237"/>
        <source>%1 = %2 ± %3 %4 (profile %5)</source>
        <translation>%1 = %2 ± %3 %4 (profil %5)</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_pre_mission_page.cpp" line="244"/>
        <source>(or %1: this log cannot tell them apart for certain)</source>
        <translation>(eller %1: denne loggen kan ikke skille dem sikkert)</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_pre_mission_page.cpp" line="247"/>
        <source>The model check did not run: the answer uses the profile&apos;s compressibility and thermal expansion.</source>
        <translation>Modellsjekken ble ikke kjørt: svaret bruker profilens kompressibilitet og termiske utvidelse.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_pre_mission_page.cpp" line="248"/>
        <source>The model check found no missing physics: the answer uses the profile&apos;s constants.</source>
        <translation>Modellsjekken fant ingen manglende fysikk: svaret bruker profilens konstanter.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_pre_mission_page.cpp" line="249"/>
        <source>Terms the answer uses: %1.</source>
        <translation>Ledd svaret bruker: %1.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_pre_mission_page.cpp" line="251"/>
        <source>Mass drift %1 g/h: the answer is the mass at the end of the log; add the drift until the deployment day.</source>
        <translation>Massedrift %1 g/t: svaret er massen ved loggens slutt; legg til driften fram til utsettingsdagen.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_pre_mission_page.cpp" line="272"/>
        <source>default: %1</source>
        <translation>standard: %1</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_pre_mission_page.cpp" line="273"/>
        <source>Target: %1 kg/m³ at %2 dbar, %3 °C (%4).</source>
        <translation>Mål: %1 kg/m³ ved %2 dbar, %3 °C (%4).</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_pre_mission_page.cpp" line="279"/>
        <source>For neutral with the pump at zero in this water: add &lt;b&gt;%1&lt;/b&gt;%2. Next: where the grams go.</source>
        <translation>For nøytral med pumpen på null i dette vannet: legg til &lt;b&gt;%1&lt;/b&gt;%2. Neste: hvor grammene skal.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_pre_mission_page.cpp" line="281"/>
        <source> (remove %1 g)</source>
        <translation> (ta ut %1 g)</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_pre_mission_page.cpp" line="201"/>
        <source>history, %1</source>
        <translation>historikk, %1</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_pre_mission_page.cpp" line="204"/>
        <source>What the bottles hold now is not in the history: capacities are checked against half-full bottles.</source>
        <translation>Hva flaskene inneholder nå, står ikke i historikken: kapasitetene sjekkes mot halvfulle flasker.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_pre_mission_page.cpp" line="209"/>
        <source>Installed now (%1): %2.</source>
        <translation>Montert nå (%1): %2.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_pre_mission_page.cpp" line="220"/>
        <source>The log does not show the glider&apos;s net buoyancy: %1. Finish saves the mission to the history; plan the next deployment from a log with steady glides.</source>
        <translation>Loggen viser ikke gliderens netto oppdrift: %1. Fullfør lagrer oppdraget i historikken; planlegg neste utsetting fra en logg med jevne glidninger.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_pre_mission_page.cpp" line="301"/>
        <source>Not saved: %1</source>
        <translation>Ikke lagret: %1</translation>
    </message>
    <message>
        <location filename="../../ui/pages/glider_pre_mission_page.cpp" line="304"/>
        <source>Saved configuration %1: the mission log and its analysis.</source>
        <translation>Lagret konfigurasjon %1: oppdragsloggen og analysen.</translation>
    </message>
</context>
<context>
    <name>auv::ui::HelpDialog</name>
    <message>
        <location filename="../../ui/widgets/help_dialog.cpp" line="18"/>
        <source>auvballast - technician&apos;s guide</source>
        <translation>auvballast - veiledning for teknikere</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/help_dialog.cpp" line="42"/>
        <source>The guide was not found at %1.</source>
        <translation>Fant ikke veiledningen i %1.</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/help_dialog.cpp" line="45"/>
        <source>&amp;Close</source>
        <translation>&amp;Lukk</translation>
    </message>
</context>
<context>
    <name>auv::ui::LinkedChartView</name>
    <message>
        <location filename="../../ui/widgets/linked_chart_view.cpp" line="133"/>
        <source>Wheel or +/-: zoom in time. Drag or arrow keys: move in time. Double-click or Home: whole log. All three charts follow.</source>
        <translation>Hjul eller +/-: zoom i tid. Dra eller piltaster: flytt i tid. Dobbeltklikk eller Home: hele loggen. Alle tre diagrammene følger.</translation>
    </message>
</context>
<context>
    <name>auv::ui::LogImportPage</name>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="38"/>
        <source>cells that are not numbers</source>
        <translation>celler som ikke er tall</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="39"/>
        <source>rows with the wrong number of cells</source>
        <translation>rader med feil antall celler</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="40"/>
        <source>rows without a time</source>
        <translation>rader uten tid</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="41"/>
        <source>rows going back in time</source>
        <translation>rader som går tilbake i tid</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="42"/>
        <source>rows repeating the previous time (merged)</source>
        <translation>rader med samme tid som forrige (slått sammen)</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="43"/>
        <source>repeated times with different values</source>
        <translation>gjentatte tider med ulike verdier</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="44"/>
        <source>fill values or huge numbers (blanked)</source>
        <translation>fyllverdier eller enorme tall (tømt)</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="45"/>
        <source>a last line cut short</source>
        <translation>en siste linje som er kuttet</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="46"/>
        <source>overlong lines</source>
        <translation>for lange linjer</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="47"/>
        <source>comment lines among the rows</source>
        <translation>kommentarlinjer blant radene</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="48"/>
        <source>columns without a unit (unit assumed)</source>
        <translation>kolonner uten enhet (enhet antatt)</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="49"/>
        <source>columns without a name (ignored)</source>
        <translation>kolonner uten navn (ignorert)</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="50"/>
        <source>repeated column names (renamed)</source>
        <translation>gjentatte kolonnenavn (omdøpt)</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="51"/>
        <source>no line end after the last row</source>
        <translation>ingen linjeslutt etter siste rad</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="52"/>
        <source>long gaps in time</source>
        <translation>lange opphold i tid</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="53"/>
        <source>times without a zone (UTC assumed)</source>
        <translation>tider uten sone (UTC antatt)</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="82"/>
        <source>Import the mission log</source>
        <translation>Importer oppdragsloggen</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="83"/>
        <source>Choose the log of the mission, or drop the file onto this page. The format is recognised from the content, not the file name.</source>
        <translation>Velg loggen fra oppdraget, eller slipp filen på denne siden. Formatet gjenkjennes fra innholdet, ikke filnavnet.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="416"/>
        <source>Installed masses taken from the log&apos;s configuration line; check them below.</source>
        <translation>Monterte masser hentet fra loggens konfigurasjonslinje; kontroller dem nedenfor.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="428"/>
        <source>Nothing installed?</source>
        <translation>Ingenting montert?</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="429"/>
        <source>Every installed mass is 0 kg. If adjustment weights were in the vehicle during this mission, enter them under &quot;Adjustment weight installed during this mission&quot; first: the analysis would otherwise put their weight into the vehicle&apos;s own balance. Analyse with nothing installed?</source>
        <translation>Alle monterte masser er 0 kg. Hvis justeringsvekter satt i fartøyet under dette oppdraget, før dem først inn under «Justeringsvekt montert under dette oppdraget»: ellers legger analysen vekten deres inn i fartøyets egen balanse. Analysere med ingenting montert?</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="94"/>
        <source>&amp;Import</source>
        <translation>&amp;Importer</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="94"/>
        <source>Read the file named on the left.</source>
        <translation>Les filen som er angitt til venstre.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="104"/>
        <source> °</source>
        <translation> °</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="105"/>
        <source>How closely the pitch sensor reads the hull&apos;s pitch, from a level check on the dock (the hull level, the reading compared). The analysis finds the sensor&apos;s offset from the log either way; a checked sensor lets it narrow the net buoyancy and CG. Leave &quot;not checked&quot; when nobody checked it: the analysis then allows up to a degree.</source>
        <translation>Hvor nøyaktig stampesensoren leser skrogets stamp, fra en vaterkontroll på kaia (skroget i vater, avlesningen sammenlignet). Analysen finner sensorens avvik fra loggen uansett; en kontrollert sensor lar den snevre inn netto oppdrift og tyngdepunkt. La stå «ikke kontrollert» når ingen har kontrollert den: analysen tillater da opptil en grad.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="109"/>
        <source>not checked</source>
        <translation>ikke kontrollert</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="115"/>
        <source>&amp;Pitch sensor level check, within ±</source>
        <translation>&amp;Stampesensor kontrollert i vater, innenfor ±</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="125"/>
        <source>How much of the file has been read.</source>
        <translation>Hvor mye av filen som er lest.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="126"/>
        <source>&amp;Cancel import</source>
        <translation>&amp;Avbryt import</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="126"/>
        <source>Stop reading; nothing of this file is kept.</source>
        <translation>Stopp lesingen; ingenting fra denne filen beholdes.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="128"/>
        <source>↓ Drop a log file here ↓</source>
        <translation>↓ Slipp en loggfil her ↓</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="143"/>
        <source>The first problems of each kind, with the line and what to do.</source>
        <translation>De første problemene av hver type, med linje og hva du bør gjøre.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="146"/>
        <source>Log file:</source>
        <translation>Loggfil:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="175"/>
        <source>Cancelling…</source>
        <translation>Avbryter…</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="242"/>
        <source>Mission log</source>
        <translation>Oppdragslogg</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="290"/>
        <source>Reading %1…</source>
        <translation>Leser %1…</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="314"/>
        <source>Read completely.</source>
        <translation>Ferdig lest.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="325"/>
        <source>Import cancelled at %1 %; nothing of this file was kept.</source>
        <translation>Importen ble avbrutt ved %1 %; ingenting fra denne filen ble beholdt.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="329"/>
        <source>Cannot read this file: %1</source>
        <translation>Kan ikke lese denne filen: %1</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="376"/>
        <source>depth</source>
        <translation>dybde</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="377"/>
        <source>commanded depth</source>
        <translation>kommandert dybde</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="378"/>
        <source>pitch</source>
        <translation>stamp</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="379"/>
        <source>commanded pitch</source>
        <translation>kommandert stamp</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="380"/>
        <source>roll</source>
        <translation>rull</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="385"/>
        <source>%1 × %2</source>
        <translation>%1 × %2</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="388"/>
        <source>&lt;b&gt;%1&lt;/b&gt; (%2): &lt;b&gt;%3 rows&lt;/b&gt; × &lt;b&gt;%4 channels&lt;/b&gt; over %5 h. Skipped %6 rows, merged %7, blanked %8 cells.&lt;br&gt;Plotted channels: %9&lt;br&gt;%10</source>
        <translation>&lt;b&gt;%1&lt;/b&gt; (%2): &lt;b&gt;%3 rader&lt;/b&gt; × &lt;b&gt;%4 kanaler&lt;/b&gt; over %5 t. Hoppet over %6 rader, slo sammen %7, tømte %8 celler.&lt;br&gt;Plottede kanaler: %9&lt;br&gt;%10</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="398"/>
        <source>Nothing was skipped or changed.</source>
        <translation>Ingenting ble hoppet over eller endret.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="398"/>
        <source>Why: %1.</source>
        <translation>Hvorfor: %1.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="95"/>
        <source>&amp;Map columns…</source>
        <translation>&amp;Koble kolonner…</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="88"/>
        <source>The mission log: a file, several files of one mission separated by &quot;; &quot;, or the folder the vehicle&apos;s files are in (type or paste it, or drop the folder here).</source>
        <translation>Oppdragsloggen: en fil, flere filer fra ett oppdrag skilt med «; », eller mappen fartøyets filer ligger i (skriv eller lim den inn, eller slipp mappen her).</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="91"/>
        <source>B&amp;rowse…</source>
        <translation>&amp;Bla gjennom…</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="92"/>
        <source>Choose the log file, or several files of one mission (they are merged on time).</source>
        <translation>Velg loggfilen, eller flere filer fra ett oppdrag (de flettes etter tid).</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="96"/>
        <source>Say which column of a vendor text log is the time, the depth, the pitch… and read it again.</source>
        <translation>Angi hvilken kolonne i en leverandørs tekstlogg som er tiden, dybden, stampen … og les den på nytt.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="97"/>
        <source>Adjustment weight installed &amp;during this mission</source>
        <translation>Justeringsvekter montert &amp;under denne misjonen</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="99"/>
        <source>The kit pieces that were in the vehicle while it flew this log, per point. The analysis needs the weight the vehicle flew with.</source>
        <translation>Vektstykkene som satt i fartøyet mens det gikk denne loggen, per punkt. Analysen trenger vekten fartøyet gikk med.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="198"/>
        <source> kg</source>
        <translation> kg</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="199"/>
        <source>Kit pieces at %1 during the logged mission, kg (what was installed before it flew, not a planned change).</source>
        <translation>Vektstykker ved %1 under den loggede misjonen, kg (det som var montert før turen, ikke en planlagt endring).</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="243"/>
        <source>Mission logs (*.csv *.txt *.log *.dat *.asc *.dba *.nc *.gz *.dbd *.ebd *.sbd *.tbd *.mbd *.nbd *.dcd *.ecd *.scd *.tcd *.mcd *.ncd);;All files (*)</source>
        <translation>Oppdragslogger (*.csv *.txt *.log *.dat *.asc *.dba *.nc *.gz *.dbd *.ebd *.sbd *.tbd *.mbd *.nbd *.dcd *.ecd *.scd *.tcd *.mcd *.ncd);;Alle filer (*)</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="272"/>
        <source>The saved column mapping is damaged and was not used: %1</source>
        <translation>Den lagrede kolonnekoblingen er skadet og ble ikke brukt: %1</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="290"/>
        <source>%1 and %2 more</source>
        <translation>%1 og %2 til</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="314"/>
        <source>Read completely with the column mapping.</source>
        <translation>Lest fullstendig med kolonnekoblingen.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="319"/>
        <source>Read, but no depth or pressure column was recognised: say which column is which.</source>
        <translation>Lest, men ingen dybde- eller trykkolonne ble gjenkjent: angi hvilken kolonne som er hva.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/log_import_page.cpp" line="359"/>
        <source>The mapping could not be saved: %1</source>
        <translation>Koblingen kunne ikke lagres: %1</translation>
    </message>
</context>
<context>
    <name>auv::ui::ModelCheckPage</name>
    <message>
        <location filename="../../ui/pages/model_check_page.cpp" line="296"/>
        <source>The check&apos;s fit and the analysis (%1) differ by %2 kg: the uncertainty includes that difference, so the plan&apos;s safety margin covers both.</source>
        <translation>Sjekkens tilpasning og analysen (%1) skiller seg med %2 kg: usikkerheten tar med den forskjellen, så planens sikkerhetsmargin dekker begge.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/model_check_page.cpp" line="50"/>
        <source>Model check: what the model leaves out</source>
        <translation>Modellsjekk: hva modellen utelater</translation>
    </message>
    <message>
        <location filename="../../ui/pages/model_check_page.cpp" line="51"/>
        <source>The recording is compared with the vehicle model replaying the mission. Physics the model lacks is named, fitted and kept only if it also improves data it was not fitted on.</source>
        <translation>Opptaket sammenlignes med fartøysmodellen som gjenspiller misjonen. Fysikk modellen mangler navngis, tilpasses og beholdes bare hvis den også forbedrer data den ikke ble tilpasset på.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/model_check_page.cpp" line="58"/>
        <source>The model check is running (about a second for a few hours of log).</source>
        <translation>Modellsjekken kjører (omtrent ett sekund for noen timers logg).</translation>
    </message>
    <message>
        <location filename="../../ui/pages/model_check_page.cpp" line="71"/>
        <source>The channel shown: recorded, the model with its ballast state only, and with the accepted terms. The one the model misses most is chosen first.</source>
        <translation>Kanalen som vises: opptaket, modellen med bare ballasttilstanden, og med de aksepterte leddene. Den modellen bommer mest på velges først.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/model_check_page.cpp" line="75"/>
        <source>Sho&amp;w:</source>
        <translation>&amp;Vis:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/model_check_page.cpp" line="77"/>
        <source>the &amp;difference recorded − model</source>
        <translation>&amp;differansen opptak − modell</translation>
    </message>
    <message>
        <location filename="../../ui/pages/model_check_page.cpp" line="79"/>
        <source>Plot recorded minus model (with the ballast state only, and with the accepted terms) instead of the values: small misfits become visible.</source>
        <translation>Tegn opptak minus modell (med bare ballasttilstanden, og med de aksepterte leddene) i stedet for verdiene: små avvik blir synlige.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/model_check_page.cpp" line="89"/>
        <source>time since start [min]</source>
        <translation>tid siden start [min]</translation>
    </message>
    <message>
        <location filename="../../ui/pages/model_check_page.cpp" line="97"/>
        <source>recorded</source>
        <translation>opptak</translation>
    </message>
    <message>
        <location filename="../../ui/pages/model_check_page.cpp" line="97"/>
        <location filename="../../ui/pages/model_check_page.cpp" line="365"/>
        <source>model, ballast state only</source>
        <translation>modell, bare ballasttilstand</translation>
    </message>
    <message>
        <location filename="../../ui/pages/model_check_page.cpp" line="97"/>
        <location filename="../../ui/pages/model_check_page.cpp" line="366"/>
        <source>model with the accepted terms</source>
        <translation>modell med aksepterte ledd</translation>
    </message>
    <message>
        <location filename="../../ui/pages/model_check_page.cpp" line="117"/>
        <source>Accept: term</source>
        <translation>Aksepter: ledd</translation>
    </message>
    <message>
        <location filename="../../ui/pages/model_check_page.cpp" line="117"/>
        <source>Value ± σ</source>
        <translation>Verdi ± σ</translation>
    </message>
    <message>
        <location filename="../../ui/pages/model_check_page.cpp" line="117"/>
        <source>Held-out RMS without → with</source>
        <translation>RMS på holdt-ut data uten → med</translation>
    </message>
    <message>
        <location filename="../../ui/pages/model_check_page.cpp" line="123"/>
        <source>Physics the model lacks, best first. Tick a term to accept it (Space toggles the selected row); accepted terms go into the vehicle model for the next mission.</source>
        <translation>Fysikk modellen mangler, beste først. Kryss av et ledd for å akseptere det (mellomrom veksler valgt rad); aksepterte ledd går inn i fartøysmodellen for neste misjon.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/model_check_page.cpp" line="192"/>
        <source>No log imported: go back to the import page.</source>
        <translation>Ingen logg importert: gå tilbake til importsiden.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/model_check_page.cpp" line="199"/>
        <source>Checking the model against the recording…</source>
        <translation>Sjekker modellen mot opptaket …</translation>
    </message>
    <message>
        <location filename="../../ui/pages/model_check_page.cpp" line="248"/>
        <source>The model check cannot run on this log: %1</source>
        <translation>Modellsjekken kan ikke kjøres på denne loggen: %1</translation>
    </message>
    <message>
        <location filename="../../ui/pages/model_check_page.cpp" line="254"/>
        <source>Model: %1.</source>
        <translation>Modell: %1.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/model_check_page.cpp" line="409"/>
        <source>In %1 % of the resampled fits the log chose %2 instead; the answer&apos;s uncertainty includes that.</source>
        <translation>I %1 % av de omsamplede tilpasningene valgte loggen %2 i stedet; usikkerheten i svaret tar med det.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/model_check_page.cpp" line="518"/>
        <source>Saved configuration %1: the mission log and its analysis.</source>
        <translation>Lagret konfigurasjon %1: oppdragsloggen og analysen.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/model_check_page.cpp" line="262"/>
        <location filename="../../ui/pages/model_check_page.cpp" line="364"/>
        <source>%1 [%2]</source>
        <translation>%1 [%2]</translation>
    </message>
    <message>
        <location filename="../../ui/pages/model_check_page.cpp" line="263"/>
        <source> - largest mismatch</source>
        <translation> – størst avvik</translation>
    </message>
    <message>
        <location filename="../../ui/pages/model_check_page.cpp" line="363"/>
        <source>difference [%1]</source>
        <translation>differanse [%1]</translation>
    </message>
    <message>
        <location filename="../../ui/pages/model_check_page.cpp" line="365"/>
        <source>recorded − model, ballast state only</source>
        <translation>opptak − modell, bare ballasttilstand</translation>
    </message>
    <message>
        <location filename="../../ui/pages/model_check_page.cpp" line="366"/>
        <source>recorded − model with the accepted terms</source>
        <translation>opptak − modell med aksepterte ledd</translation>
    </message>
    <message>
        <location filename="../../ui/pages/model_check_page.cpp" line="367"/>
        <source>%1: RMS recorded − model %2 → %3 %4 (ballast state only → with the accepted terms)</source>
        <translation>%1: RMS opptak − modell %2 → %3 %4 (bare ballasttilstand → med aksepterte ledd)</translation>
    </message>
    <message>
        <location filename="../../ui/pages/model_check_page.cpp" line="389"/>
        <source>No missing physics found: the model with its ballast state explains this log within its noise.</source>
        <translation>Ingen manglende fysikk funnet: modellen med ballasttilstanden forklarer denne loggen innenfor støyen.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/model_check_page.cpp" line="406"/>
        <source>This log cannot tell it from: %1</source>
        <translation>Denne loggen kan ikke skille det fra: %1</translation>
    </message>
    <message>
        <location filename="../../ui/pages/model_check_page.cpp" line="415"/>
        <source>%1 ± %2 %3</source>
        <translation>%1 ± %2 %3</translation>
    </message>
    <message>
        <location filename="../../ui/pages/model_check_page.cpp" line="417"/>
        <source>%1 → %2 %3</source>
        <translation>%1 → %2 %3</translation>
    </message>
    <message>
        <location filename="../../ui/pages/model_check_page.cpp" line="418"/>
        <source>Held-out simulation RMS of %1, without and with this term (fitted on one half of the dives/legs, scored on the other).</source>
        <translation>Simulerings-RMS for %1 på holdt-ut data, uten og med dette leddet (tilpasset på den ene halvdelen av dykkene/etappene, vurdert på den andre).</translation>
    </message>
    <message>
        <location filename="../../ui/pages/model_check_page.cpp" line="431"/>
        <source>&lt;b&gt;%1&lt;/b&gt; acts where: %2</source>
        <translation>&lt;b&gt;%1&lt;/b&gt; virker der: %2</translation>
    </message>
    <message>
        <location filename="../../ui/pages/model_check_page.cpp" line="432"/>
        <source>&lt;b&gt;Where the ballast-only model misses&lt;/b&gt;:</source>
        <translation>&lt;b&gt;Der modellen med bare ballasttilstand bommer&lt;/b&gt;:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/model_check_page.cpp" line="444"/>
        <source>%1, %2: %3</source>
        <translation>%1, %2: %3</translation>
    </message>
    <message>
        <location filename="../../ui/pages/model_check_page.cpp" line="445"/>
        <source>Cannot be told apart: %1</source>
        <translation>Kan ikke skilles: %1</translation>
    </message>
    <message>
        <location filename="../../ui/pages/model_check_page.cpp" line="490"/>
        <source>The accepted terms could not be added to the vehicle model: %1</source>
        <translation>De godtatte leddene kunne ikke legges til fartøymodellen: %1</translation>
    </message>
    <message>
        <location filename="../../ui/pages/model_check_page.cpp" line="515"/>
        <source>Not saved: %1</source>
        <translation>Ikke lagret: %1</translation>
    </message>
    <message>
        <location filename="../../ui/pages/model_check_page.cpp" line="281"/>
        <source>%1 samples in %2 dives/legs.</source>
        <translation>%1 målinger i %2 dykk/etapper.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/model_check_page.cpp" line="284"/>
        <source>Ballast state: net buoyancy &lt;b&gt;%1&lt;/b&gt;, CG − CB x &lt;b&gt;%2&lt;/b&gt;, y &lt;b&gt;%3&lt;/b&gt; (model ballast state alone: %4 kg).</source>
        <translation>Ballasttilstand: netto oppdrift &lt;b&gt;%1&lt;/b&gt;, CG − CB x &lt;b&gt;%2&lt;/b&gt;, y &lt;b&gt;%3&lt;/b&gt; (modellen med bare ballasttilstand: %4 kg).</translation>
    </message>
    <message>
        <location filename="../../ui/pages/model_check_page.cpp" line="301"/>
        <source>Net buoyancy with the accepted terms &lt;b&gt;%1&lt;/b&gt; (ballast state alone: %2 kg).</source>
        <translation>Netto oppdrift med de godtatte leddene &lt;b&gt;%1&lt;/b&gt; (bare ballasttilstand: %2 kg).</translation>
    </message>
    <message>
        <location filename="../../ui/pages/model_check_page.cpp" line="286"/>
        <location filename="../../ui/pages/model_check_page.cpp" line="298"/>
        <location filename="../../ui/pages/model_check_page.cpp" line="302"/>
        <source> kg</source>
        <translation> kg</translation>
    </message>
    <message>
        <location filename="../../ui/pages/model_check_page.cpp" line="287"/>
        <source> mm</source>
        <translation> mm</translation>
    </message>
</context>
<context>
    <name>auv::ui::NumberInput</name>
    <message>
        <location filename="../../ui/widgets/number_input.cpp" line="161"/>
        <source>Enter a number.</source>
        <translation>Skriv inn et tall.</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/number_input.cpp" line="163"/>
        <source>&apos;%1&apos; is not a number.</source>
        <translation>«%1» er ikke et tall.</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/number_input.cpp" line="165"/>
        <source>The lowest accepted value is %1 %2.</source>
        <translation>Laveste godtatte verdi er %1 %2.</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/number_input.cpp" line="167"/>
        <source>The highest accepted value is %1 %2.</source>
        <translation>Høyeste godtatte verdi er %1 %2.</translation>
    </message>
</context>
<context>
    <name>auv::ui::OperatorWizard</name>
    <message>
        <location filename="../../ui/wizard/operator_wizard.cpp" line="41"/>
        <source>auvballast - ballast wizard</source>
        <translation>auvballast - ballastveiviser</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/operator_wizard.cpp" line="46"/>
        <source>&lt; &amp;Back</source>
        <translation>&lt; &amp;Tilbake</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/operator_wizard.cpp" line="47"/>
        <source>&amp;Next &gt;</source>
        <translation>&amp;Neste &gt;</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/operator_wizard.cpp" line="48"/>
        <source>&amp;Finish</source>
        <translation>&amp;Fullfør</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/operator_wizard.cpp" line="49"/>
        <source>Cancel</source>
        <translation>Avbryt</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/operator_wizard.cpp" line="50"/>
        <source>&amp;Help</source>
        <translation>&amp;Hjelp</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/operator_wizard.cpp" line="165"/>
        <source>&amp;Close without saving</source>
        <translation>&amp;Lukk uten å lagre</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/operator_wizard.cpp" line="166"/>
        <source>&amp;Stay</source>
        <translation>&amp;Bli</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/operator_wizard.cpp" line="174"/>
        <source>Nothing will be saved</source>
        <translation>Ingenting blir lagret</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/operator_wizard.cpp" line="175"/>
        <source>The history cannot be opened (%1), so this session cannot be saved. Your input stays in the unfinished session and is offered for resuming at the next start. Close anyway?</source>
        <translation>Historikken kan ikke åpnes (%1), så denne økten kan ikke lagres. Det du har skrevet blir i den uferdige økten og tilbys for gjenopptak ved neste start. Lukke likevel?</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/operator_wizard.cpp" line="185"/>
        <source>Close without saving?</source>
        <translation>Lukke uten å lagre?</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/operator_wizard.cpp" line="186"/>
        <source>What you entered in this session is not in the history yet. It stays in the unfinished session, which the start page offers to resume. Close anyway?</source>
        <translation>Det du har skrevet inn i denne økten er ikke i historikken ennå. Det blir i den uferdige økten, som startsiden tilbyr å gjenoppta. Lukke likevel?</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/operator_wizard.cpp" line="204"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/operator_wizard.cpp" line="256"/>
        <source>Saved</source>
        <translation>Lagret</translation>
    </message>
</context>
<context>
    <name>auv::ui::PreMissionPage</name>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="44"/>
        <source>Plan the next mission</source>
        <translation>Planlegg neste oppdrag</translation>
    </message>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="45"/>
        <source>From what the last mission showed and the water of the next one: which pieces to add or remove.</source>
        <translation>Ut fra hva forrige oppdrag viste og vannet i det neste: hvilke vektbiter som skal legges til eller fjernes.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="47"/>
        <source>What the plan starts from</source>
        <translation>Hva planen bygger på</translation>
    </message>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="62"/>
        <source>Next mission&apos;s water</source>
        <translation>Vannet i neste oppdrag</translation>
    </message>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="63"/>
        <source>&amp;Last mission&apos;s CTD</source>
        <translation>Siste oppdrags &amp;CTD</translation>
    </message>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="65"/>
        <source>Fly in the water the analysed mission measured: its temperature and salinity at its operating depth.</source>
        <translation>Kjør i vannet det analyserte oppdraget målte: temperatur og salinitet på dets operasjonsdybde.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="66"/>
        <source>&amp;Values I enter</source>
        <translation>&amp;Verdier jeg skriver inn</translation>
    </message>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="68"/>
        <source>Another area, season or depth: enter the temperature and salinity you measured or expect.</source>
        <translation>Annet område, annen årstid eller dybde: skriv inn temperaturen og saliniteten du har målt eller forventer.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="73"/>
        <source>Water temperature at the operating depth (CTD cast), in °C.</source>
        <translation>Vanntemperatur på operasjonsdybden (CTD-profil), i °C.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="74"/>
        <source>enter °C</source>
        <translation>skriv inn °C</translation>
    </message>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="75"/>
        <source>Practical salinity at the operating depth (35 = open ocean).</source>
        <translation>Praktisk salinitet på operasjonsdybden (35 = åpent hav).</translation>
    </message>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="76"/>
        <source>Depth where the vehicle spends most of the mission: the band applies there.</source>
        <translation>Dybden der fartøyet er mesteparten av oppdraget: båndet gjelder der.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="80"/>
        <source>Latitude of the area (gravity for depth to pressure).</source>
        <translation>Breddegrad for området (tyngdekraft for dybde til trykk).</translation>
    </message>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="96"/>
        <source>&amp;Temperature:</source>
        <translation>Te&amp;mperatur:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="97"/>
        <source>&amp;Salinity:</source>
        <translation>&amp;Salinitet:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="98"/>
        <source>Operating &amp;depth:</source>
        <translation>&amp;Operasjonsdybde:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="99"/>
        <source>D&amp;eepest depth:</source>
        <translation>&amp;Dypeste dybde:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="100"/>
        <source>Lat&amp;itude:</source>
        <translation>&amp;Breddegrad:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="110"/>
        <source>Policy</source>
        <translation>Strategi</translation>
    </message>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="111"/>
        <source>E&amp;xact: the whole change now</source>
        <translation>&amp;Eksakt: hele endringen nå</translation>
    </message>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="113"/>
        <source>Pieces that bring net buoyancy, pitch and roll into the bands as well as the kit allows.</source>
        <translation>Vektbiter som bringer netto oppdrift, stamp og rull inn i båndene så godt vektsettet tillater.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="114"/>
        <source>H&amp;alf-way: about half the change</source>
        <translation>H&amp;alvveis: omtrent halve endringen</translation>
    </message>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="116"/>
        <source>When the estimate is uncertain: move about half way, still never heavy.</source>
        <translation>Når estimatet er usikkert: flytt omtrent halvveis, men aldri tungt.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="117"/>
        <source>&amp;Classic: the thesis&apos;s table</source>
        <translation>&amp;Klassisk: tabellen i oppgaven</translation>
    </message>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="119"/>
        <source>The thesis&apos;s slow control loop (App. E): one smallest piece per point from the signs of the deviations. For comparison.</source>
        <translation>Oppgavens langsomme reguleringssløyfe (vedlegg E): én minste vektbit per punkt ut fra fortegnene på avvikene. Til sammenligning.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="128"/>
        <source>Also use the kit&apos;s optional pieces (HUGIN: 0.5 kg, thesis §8.1) - only if you have them.</source>
        <translation>Bruk også vektsettets valgfrie biter (HUGIN: 0,5 kg, oppgaven §8.1) - bare hvis du har dem.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="198"/>
        <source>Use the optional %1 &amp;piece</source>
        <translation>Bruk den valgfrie %1-b&amp;iten</translation>
    </message>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="253"/>
        <source>Nothing to plan from: %1 Finish saves the mission to the history; plan the next mission from a log that shows the net buoyancy.</source>
        <translation>Ingenting å planlegge ut fra: %1 Fullfør lagrer oppdraget i historikken; planlegg neste oppdrag ut fra en logg som viser netto oppdrift.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="256"/>
        <source>Nothing to plan from: %1</source>
        <translation>Ingenting å planlegge ut fra: %1</translation>
    </message>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="266"/>
        <source>neutral</source>
        <translation>nøytral</translation>
    </message>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="267"/>
        <source>too light</source>
        <translation>for lett</translation>
    </message>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="268"/>
        <source>too heavy</source>
        <translation>for tung</translation>
    </message>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="434"/>
        <source>Saved configuration %1: the mission log and its analysis.</source>
        <translation>Lagret konfigurasjon %1: oppdragsloggen og analysen.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="278"/>
        <source>No net buoyancy was measured: the recorded weight against the buoyancy gives &lt;b&gt;%1 kg&lt;/b&gt; (%2), and the classic table works from the deviations.</source>
        <translation>Netto oppdrift ble ikke målt: registrert vekt mot oppdriften gir &lt;b&gt;%1 kg&lt;/b&gt; (%2), og den klassiske tabellen bruker avvikene.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="285"/>
        <source>CG − CB: x %1, y %2</source>
        <translation>CG − CB: x %1, y %2</translation>
    </message>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="286"/>
        <source> (y that levels it at %1 rpm)</source>
        <translation> (y som gir null rull ved %1 o/min)</translation>
    </message>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="294"/>
        <source>From %1</source>
        <translation>Fra %1</translation>
    </message>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="297"/>
        <source>; its water measured %1 (%2 days ago)</source>
        <translation>; vannet målt %1 (for %2 dager siden)</translation>
    </message>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="304"/>
        <source>Installed now (%1): %2.</source>
        <translation>Montert nå (%1): %2.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="306"/>
        <source>The last mission&apos;s water is older than one month (thesis §5.5.3): measure the temperature again and enter it.</source>
        <translation>Vannet fra siste oppdrag er eldre enn én måned (oppgaven §5.5.3): mål temperaturen på nytt og skriv den inn.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="359"/>
        <source>Deepest depth: %1 m is shallower than the operating depth (%2 m); enter the deepest depth the mission goes to, at least %2 m.</source>
        <translation>Største dybde: %1 m er grunnere enn operasjonsdybden (%2 m); skriv inn den største dybden oppdraget går til, minst %2 m.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="366"/>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="390"/>
        <source>Enter the next mission&apos;s water temperature.</source>
        <translation>Skriv inn vanntemperaturen for neste oppdrag.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="385"/>
        <source>In-situ density %1 kg/m³</source>
        <translation>In situ-tetthet %1 kg/m³</translation>
    </message>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="431"/>
        <source>Not saved: %1</source>
        <translation>Ikke lagret: %1</translation>
    </message>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="283"/>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="272"/>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="405"/>
        <source> kg</source>
        <translation> kg</translation>
    </message>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="78"/>
        <source>Deepest depth the mission goes to (the analysed log&apos;s deepest by default): the vehicle must not be heavy there either. At least the operating depth.</source>
        <translation>Største dybde oppdraget går til (den analyserte loggens største som standard): fartøyet må ikke være tungt der heller. Minst operasjonsdybden.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="407"/>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="409"/>
        <source>°</source>
        <translation>°</translation>
    </message>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="271"/>
        <source>Net buoyancy &lt;b&gt;%1&lt;/b&gt; (%2) in %3 kg/m³ water at %4 m (%5 °C, %6 PSU).</source>
        <translation>Netto oppdrift &lt;b&gt;%1&lt;/b&gt; (%2) i %3 kg/m³ vann på %4 m (%5 °C, %6 PSU).</translation>
    </message>
    <message>
        <location filename="../../ui/pages/pre_mission_page.cpp" line="402"/>
        <source>Plan: %1 piece(s) to handle; afterwards net buoyancy %2, pitch %3, roll %4 at %5 m.</source>
        <translation>Plan: %1 vektbit(er) å håndtere; etterpå netto oppdrift %2, stamp %3, rull %4 på %5 m.</translation>
    </message>
</context>
<context>
    <name>auv::ui::RollTestPage</name>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="26"/>
        <source>Bow, port:</source>
        <translation>Baug, babord:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="26"/>
        <source>Bow, starboard:</source>
        <translation>Baug, styrbord:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="27"/>
        <source>Aft, upper:</source>
        <translation>Akter, øvre:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="27"/>
        <source>Aft, lower:</source>
        <translation>Akter, nedre:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="32"/>
        <source>Slocum roll test</source>
        <translation>Rulltest av Slocum</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="36"/>
        <source>Bottles set after the tank st&amp;ep</source>
        <translation>&amp;Flasker satt etter tanktrinnet</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="38"/>
        <source>Tick when you have changed the bottles as the tank step said: the roll test then refers to these contents.</source>
        <translation>Kryss av når du har endret flaskene slik tanktrinnet sa: rulltesten gjelder da dette innholdet.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="40"/>
        <source>Bottles now</source>
        <translation>Flasker nå</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="46"/>
        <location filename="../../ui/pages/roll_test_page.cpp" line="104"/>
        <source> g</source>
        <translation> g</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="47"/>
        <source>Lead shot actually in this bottle after the tank step, in grams.</source>
        <translation>Blyhagl som faktisk er i denne flasken etter tanktrinnet, i gram.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="50"/>
        <source>Fill in the tank-step &amp;result</source>
        <translation>Fyll inn &amp;resultatet fra tanktrinnet</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="52"/>
        <source>Copy the bottle contents the tank step recommended (edit them if you set something else).</source>
        <translation>Kopier flaskeinnholdet tanktrinnet anbefalte (rett dem hvis du satte noe annet).</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="58"/>
        <source>Roll &amp;test done</source>
        <translation>Rull&amp;test utført</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="60"/>
        <source>Untick to compute without a roll test (the CG height then comes from the profile).</source>
        <translation>Fjern krysset for å beregne uten rulltest (tyngdepunktets høyde tas da fra profilen).</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="61"/>
        <location filename="../../ui/pages/roll_test_page.cpp" line="110"/>
        <location filename="../../ui/pages/roll_test_page.cpp" line="170"/>
        <source> rad</source>
        <translation> rad</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="63"/>
        <source> m</source>
        <translation> m</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="64"/>
        <source>Horizontal distance from the hull axis to where the mass hangs (the hull radius for a mass on the rail).</source>
        <translation>Horisontal avstand fra skrogaksen til der massen henger (skrogradien for en masse på skinnen).</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="68"/>
        <source>Mass hung</source>
        <translation>Hengt masse</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="68"/>
        <source>Rail</source>
        <translation>Skinne</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="33"/>
        <source>Wings off, glider hanging free from the nose hook and tail loop. Read the roll the glider reports with nothing hung, then with each known mass hung on a wing rail.</source>
        <translation>Vingene av, glideren hengende fritt fra nesekroken og halestroppen. Les av rullen glideren melder uten noe opphengt, deretter med hver kjente masse hengt på en vingeskinne.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="62"/>
        <source>The roll the glider reports with nothing hung, in radians (starboard down positive).</source>
        <translation>Rullen glideren melder uten noe opphengt, i radianer (styrbord ned positiv).</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="68"/>
        <source>Roll reading</source>
        <translation>Rullavlesning</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="71"/>
        <source>One row per applied mass: its submerged mass, the rail it hangs on and the roll the glider reports with it hanging.</source>
        <translation>Én rad per påført masse: dens neddykkede masse, skinnen den henger på og rullen glideren melder mens den henger der.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="72"/>
        <source>&amp;Add mass</source>
        <translation>&amp;Legg til masse</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="74"/>
        <source>Add a row for another applied mass.</source>
        <translation>Legg til en rad for enda en påhengt masse.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="77"/>
        <source>Re&amp;move last</source>
        <translation>Fjern &amp;siste</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="79"/>
        <source>Remove the last applied mass.</source>
        <translation>Fjern den siste påhengte massen.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="82"/>
        <source>Roll readings</source>
        <translation>Rullavlesninger</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="86"/>
        <source>&amp;Initial roll:</source>
        <translation>&amp;Startrull:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="87"/>
        <source>&amp;Lever arm:</source>
        <translation>&amp;Momentarm:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="96"/>
        <source>Disk weights and roll battery now</source>
        <translation>Skivevekter og rullbatteri nå</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="99"/>
        <source>Top</source>
        <translation>Øverst</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="100"/>
        <source>Bottom</source>
        <translation>Nederst</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="102"/>
        <source>Column %1</source>
        <translation>Kolonne %1</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="105"/>
        <source>Disk weight in this seat, in grams (0 = empty).</source>
        <translation>Skivevekt i dette setet, i gram (0 = tomt).</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="111"/>
        <source>Roll battery angle now; positive = swung to starboard.</source>
        <translation>Rullbatteriets vinkel nå; positiv = dreid mot styrbord.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="112"/>
        <source>Battery:</source>
        <translation>Batteri:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="162"/>
        <source> kg</source>
        <translation> kg</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="163"/>
        <source>Submerged (apparent) mass of the weight you hung, in kg.</source>
        <translation>Massen i vann (tilsynelatende) av vekten du hengte på, i kg.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="166"/>
        <source>Port</source>
        <translation>Babord</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="167"/>
        <source>Starboard</source>
        <translation>Styrbord</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="168"/>
        <source>The wing rail the mass hangs on.</source>
        <translation>Vingeskinnen massen henger på.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="171"/>
        <source>The roll the glider reports with this mass hanging and the glider at rest, in radians.</source>
        <translation>Rullen glideren melder med denne massen hengende og glideren i ro, i radianer.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="276"/>
        <source>h-arm &lt;b&gt;%1 mm&lt;/b&gt; (each mass: %2 mm; spread %3 mm). G sits &lt;b&gt;%4 mm to %5&lt;/b&gt; of the hull axis and %6 mm below it. Target h-arm %7 mm.</source>
        <translation>h-arm &lt;b&gt;%1 mm&lt;/b&gt; (hver masse: %2 mm; spredning %3 mm). G ligger &lt;b&gt;%4 mm mot %5&lt;/b&gt; fra skrogaksen og %6 mm under den. Mål for h-arm %7 mm.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="282"/>
        <source>starboard</source>
        <translation>styrbord</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="282"/>
        <source>port</source>
        <translation>babord</translation>
    </message>
    <message>
        <location filename="../../ui/pages/roll_test_page.cpp" line="286"/>
        <source>No roll test: the result will use the profile&apos;s CG height.</source>
        <translation>Ingen rulltest: resultatet bruker tyngdepunktshøyden fra profilen.</translation>
    </message>
</context>
<context>
    <name>auv::ui::StartPage</name>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="35"/>
        <source>Start: configuration and mode</source>
        <translation>Start: konfigurasjon og modus</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="36"/>
        <source>Continue a vehicle configuration from the history or start a new one, then choose what to do.</source>
        <translation>Fortsett en fartøykonfigurasjon fra historikken eller start en ny, og velg så hva du vil gjøre.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="45"/>
        <source>&amp;Resume</source>
        <translation>&amp;Fortsett</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="47"/>
        <source>Continue the unfinished session where you left it.</source>
        <translation>Fortsett den uferdige økten der du slapp.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="50"/>
        <source>&amp;Discard</source>
        <translation>&amp;Forkast</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="52"/>
        <source>Delete the unfinished session and start afresh.</source>
        <translation>Slett den uferdige økten og begynn på nytt.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="63"/>
        <source>Search ID, payload, area, water type or vehicle</source>
        <translation>Søk i ID, nyttelast, område, vanntype eller fartøy</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="64"/>
        <source>Type part of a configuration ID, payload note, area, water type or vehicle name.</source>
        <translation>Skriv en del av en konfigurasjons-ID, nyttelastnotat, område, vanntype eller fartøynavn.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="67"/>
        <source>&amp;Search:</source>
        <translation>&amp;Søk:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="72"/>
        <source>Configuration</source>
        <translation>Konfigurasjon</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="72"/>
        <source>Vehicle</source>
        <translation>Fartøy</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="72"/>
        <source>Payload</source>
        <translation>Nyttelast</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="72"/>
        <source>Area / water</source>
        <translation>Område / vann</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="73"/>
        <source>Last activity</source>
        <translation>Siste aktivitet</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="80"/>
        <source>Recent configurations, newest first. The first row starts a new configuration.</source>
        <translation>Nylige konfigurasjoner, nyeste først. Første rad starter en ny konfigurasjon.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="82"/>
        <source>Last state</source>
        <translation>Siste tilstand</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="93"/>
        <source>What do you want to do?</source>
        <translation>Hva vil du gjøre?</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="94"/>
        <source>&amp;First mission: weigh the vehicle and compute the ballast change</source>
        <translation>&amp;Første oppdrag: vei fartøyet og beregn ballastendringen</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="96"/>
        <source>No mission flown yet with this configuration: crane weighing (AUV) or tank weighing (glider).</source>
        <translation>Ingen oppdrag kjørt ennå med denne konfigurasjonen: kranveiing (AUV) eller tankveiing (glider).</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="97"/>
        <source>&amp;Post mission: import a mission log and look at the deviations</source>
        <translation>&amp;Etter oppdrag: importer en oppdragslogg og se på avvikene</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="99"/>
        <source>You have a log of a mission flown with this configuration.</source>
        <translation>Du har en logg fra et oppdrag kjørt med denne konfigurasjonen.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="100"/>
        <source>Pre &amp;mission: plan the next mission from the analysed log</source>
        <translation>Før &amp;neste oppdrag: planlegg neste oppdrag fra den analyserte loggen</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="102"/>
        <source>Plan the next mission from the last analysed mission of this configuration: needs an analysis in the history (post-mission mode) or in this session.</source>
        <translation>Planlegg neste oppdrag ut fra det sist analyserte oppdraget med denne konfigurasjonen: krever en analyse i historikken (etter oppdrag) eller i denne økten.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="143"/>
        <source>Cannot resume: %1</source>
        <translation>Kan ikke fortsette: %1</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="158"/>
        <source>The history cannot be opened (%1); you can still work, but nothing will be saved.</source>
        <translation>Historikken kan ikke åpnes (%1); du kan fortsatt arbeide, men ingenting blir lagret.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="161"/>
        <source>History: %1</source>
        <translation>Historikk: %1</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="179"/>
        <source>An unfinished session was found (saved %1): %2, configuration %3, at &quot;%4&quot;.</source>
        <translation>Fant en uferdig økt (lagret %1): %2, konfigurasjon %3, ved «%4».</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="181"/>
        <source>no vehicle yet</source>
        <translation>ikke noe fartøy ennå</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="182"/>
        <source>(no ID)</source>
        <translation>(ingen ID)</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="186"/>
        <source>An unfinished session was found but cannot be read: %1</source>
        <translation>Fant en uferdig økt, men den kan ikke leses: %1</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="208"/>
        <source>created %1</source>
        <translation>opprettet %1</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="216"/>
        <source>+ New configuration</source>
        <translation>+ Ny konfigurasjon</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="270"/>
        <source>A new configuration: you name it and choose the vehicle on the next page. Only the first-mission mode makes sense until it has flown.</source>
        <translation>En ny konfigurasjon: du gir den navn og velger fartøy på neste side. Bare første oppdrag gir mening før den har vært i sjøen.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="286"/>
        <source>&lt;b&gt;%1&lt;/b&gt; - %2, %3</source>
        <translation>&lt;b&gt;%1&lt;/b&gt; - %2, %3</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="295"/>
        <source>Installed (%1): %2</source>
        <translation>Montert (%1): %2</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="297"/>
        <source>Installed: nothing recorded yet.</source>
        <translation>Montert: ingenting registrert ennå.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="300"/>
        <source>Last mission: %1, imported %2</source>
        <translation>Siste oppdrag: %1, importert %2</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="304"/>
        <source>Last mission: none yet.</source>
        <translation>Siste oppdrag: ingen ennå.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="306"/>
        <source>Last analysis: %1</source>
        <translation>Siste analyse: %1</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="310"/>
        <source>Water temperature %1 °C measured %2 (%3 days ago)</source>
        <translation>Vanntemperatur %1 °C målt %2 (for %3 dager siden)</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="316"/>
        <source>: older than one month - measure it again before computing (thesis §5.5.3).</source>
        <translation>: eldre enn én måned - mål den på nytt før beregning (avhandlingen §5.5.3).</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="319"/>
        <source>: less than a month old, it can be reused.</source>
        <translation>: under en måned gammel, den kan brukes igjen.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/start_page.cpp" line="323"/>
        <source>No water temperature in the history: measure it before computing.</source>
        <translation>Ingen vanntemperatur i historikken: mål den før beregning.</translation>
    </message>
</context>
<context>
    <name>auv::ui::SummaryPage</name>
    <message>
        <location filename="../../ui/pages/summary_page.cpp" line="28"/>
        <source>Summary and save</source>
        <translation>Oppsummering og lagring</translation>
    </message>
    <message>
        <location filename="../../ui/pages/summary_page.cpp" line="29"/>
        <source>Finish saves all of this to the history in one step. Export the work order for the vehicle&apos;s logbook.</source>
        <translation>Fullfør lagrer alt dette i historikken i ett steg. Eksporter arbeidsordren til fartøyets loggbok.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/summary_page.cpp" line="39"/>
        <source>The work order as it will be printed (export it as PDF).</source>
        <translation>Arbeidsordren slik den blir skrevet ut (eksporter den som PDF).</translation>
    </message>
    <message>
        <location filename="../../ui/pages/summary_page.cpp" line="40"/>
        <source>Export work &amp;order (PDF)…</source>
        <translation>Eksporter &amp;arbeidsordre (PDF)…</translation>
    </message>
    <message>
        <location filename="../../ui/pages/summary_page.cpp" line="42"/>
        <source>One A4 page: vehicle, configuration, water, what to change where, the expected result and a signature line.</source>
        <translation>Én A4-side: fartøy, konfigurasjon, vann, hva som skal endres hvor, forventet resultat og en signaturlinje.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/summary_page.cpp" line="44"/>
        <source>Export &amp;JSON report…</source>
        <translation>Eksporter &amp;JSON-rapport…</translation>
    </message>
    <message>
        <location filename="../../ui/pages/summary_page.cpp" line="46"/>
        <source>The plan, the sources and what was actually installed, for other tools.</source>
        <translation>Planen, kildene og hva som faktisk ble montert, for andre verktøy.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/summary_page.cpp" line="101"/>
        <source>the mission log &lt;b&gt;%1&lt;/b&gt; with its read summary</source>
        <translation>oppdragsloggen &lt;b&gt;%1&lt;/b&gt; med innlesingssammendraget</translation>
    </message>
    <message>
        <location filename="../../ui/pages/summary_page.cpp" line="104"/>
        <source>the next mission&apos;s water: %1 m, %2 °C, %3 PSU (%4)</source>
        <translation>vannet i neste oppdrag: %1 m, %2 °C, %3 PSU (%4)</translation>
    </message>
    <message>
        <location filename="../../ui/pages/summary_page.cpp" line="108"/>
        <source>entered</source>
        <translation>skrevet inn</translation>
    </message>
    <message>
        <location filename="../../ui/pages/summary_page.cpp" line="108"/>
        <source>last mission&apos;s CTD</source>
        <translation>siste oppdrags CTD</translation>
    </message>
    <message>
        <location filename="../../ui/pages/summary_page.cpp" line="109"/>
        <source>the plan (%1 policy) as the accepted recommendation, from %2</source>
        <translation>planen (strategi %1) som godtatt anbefaling, fra %2</translation>
    </message>
    <message>
        <location filename="../../ui/pages/summary_page.cpp" line="120"/>
        <source> &lt;i&gt;(plan %1)&lt;/i&gt;</source>
        <translation> &lt;i&gt;(plan %1)&lt;/i&gt;</translation>
    </message>
    <message>
        <location filename="../../ui/pages/summary_page.cpp" line="123"/>
        <source>what is actually installed, &lt;b&gt;different from the plan&lt;/b&gt;: %1</source>
        <translation>hva som faktisk er montert, &lt;b&gt;annerledes enn planen&lt;/b&gt;: %1</translation>
    </message>
    <message>
        <location filename="../../ui/pages/summary_page.cpp" line="124"/>
        <source>what is actually installed, as planned: %1</source>
        <translation>hva som faktisk er montert, som planlagt: %1</translation>
    </message>
    <message>
        <location filename="../../ui/pages/summary_page.cpp" line="129"/>
        <source>&lt;b&gt;Finish saves to the history&lt;/b&gt; of configuration &lt;b&gt;%1&lt;/b&gt;, all together or nothing:</source>
        <translation>&lt;b&gt;Fullfør lagrer i historikken&lt;/b&gt; til konfigurasjon &lt;b&gt;%1&lt;/b&gt;, alt samlet eller ingenting:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/summary_page.cpp" line="134"/>
        <source>Checklist: %1 of %2 steps ticked.</source>
        <translation>Sjekkliste: %1 av %2 steg krysset av.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/summary_page.cpp" line="135"/>
        <source>&lt;span style=&apos;color:#b00020&apos;&gt;Not every step is ticked: go back and finish them, or enter what is actually installed.&lt;/span&gt;</source>
        <translation>&lt;span style=&apos;color:#b00020&apos;&gt;Ikke alle steg er krysset av: gå tilbake og fullfør dem, eller skriv inn hva som faktisk er montert.&lt;/span&gt;</translation>
    </message>
    <message>
        <location filename="../../ui/pages/summary_page.cpp" line="139"/>
        <source>&lt;b&gt;Expected result&lt;/b&gt;</source>
        <translation>&lt;b&gt;Forventet resultat&lt;/b&gt;</translation>
    </message>
    <message>
        <location filename="../../ui/pages/summary_page.cpp" line="152"/>
        <location filename="../../ui/pages/summary_page.cpp" line="168"/>
        <source>nothing to export</source>
        <translation>ingenting å eksportere</translation>
    </message>
    <message>
        <location filename="../../ui/pages/summary_page.cpp" line="162"/>
        <source>Work order written to %1</source>
        <translation>Arbeidsordre skrevet til %1</translation>
    </message>
    <message>
        <location filename="../../ui/pages/summary_page.cpp" line="162"/>
        <location filename="../../ui/pages/summary_page.cpp" line="170"/>
        <source>Not exported: %1</source>
        <translation>Ikke eksportert: %1</translation>
    </message>
    <message>
        <location filename="../../ui/pages/summary_page.cpp" line="170"/>
        <source>JSON report written to %1</source>
        <translation>JSON-rapport skrevet til %1</translation>
    </message>
    <message>
        <location filename="../../ui/pages/summary_page.cpp" line="179"/>
        <source>Export the work order</source>
        <translation>Eksporter arbeidsordren</translation>
    </message>
    <message>
        <location filename="../../ui/pages/summary_page.cpp" line="180"/>
        <source>PDF files (*.pdf)</source>
        <translation>PDF-filer (*.pdf)</translation>
    </message>
    <message>
        <location filename="../../ui/pages/summary_page.cpp" line="181"/>
        <source>Export the JSON report</source>
        <translation>Eksporter JSON-rapporten</translation>
    </message>
    <message>
        <location filename="../../ui/pages/summary_page.cpp" line="182"/>
        <source>JSON files (*.json)</source>
        <translation>JSON-filer (*.json)</translation>
    </message>
    <message>
        <location filename="../../ui/pages/summary_page.cpp" line="201"/>
        <source>Not saved: %1</source>
        <translation>Ikke lagret: %1</translation>
    </message>
    <message>
        <location filename="../../ui/pages/summary_page.cpp" line="204"/>
        <source>Saved configuration %1: %2the plan, the next mission&apos;s water and the installed state.</source>
        <translation>Lagret konfigurasjon %1: %2planen, vannet i neste oppdrag og montert tilstand.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/summary_page.cpp" line="206"/>
        <source>the mission log, </source>
        <translation>oppdragsloggen, </translation>
    </message>
</context>
<context>
    <name>auv::ui::TankWeighingPage</name>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="23"/>
        <source>Bow bottle, &amp;port:</source>
        <translation>Baugflaske, &amp;babord:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="24"/>
        <source>Bow bottle, &amp;starboard:</source>
        <translation>Baugflaske, &amp;styrbord:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="25"/>
        <source>Aft bottle, &amp;upper:</source>
        <translation>Akterflaske, &amp;øvre:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="26"/>
        <source>Aft bottle, &amp;lower:</source>
        <translation>Akterflaske, &amp;nedre:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="27"/>
        <source>Wing rail, p&amp;ort:</source>
        <translation>Vingeskinne, b&amp;abord:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="28"/>
        <source>Wing rail, s&amp;tarboard:</source>
        <translation>Vingeskinne, s&amp;tyrbord:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="34"/>
        <source>Slocum tank weighing</source>
        <translation>Veiing av Slocum i tank</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="35"/>
        <source>Hang the glider submerged in the tank from the two spring scales over the bow and aft ballast bottles; read both once it hangs still and level, with no air trapped.</source>
        <translation>Heng glideren nedsenket i tanken i de to fjærvektene over baug- og akterballastflaskene; les av begge når den henger stille og vannrett, uten innestengt luft.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="40"/>
        <source>Glider serial number or name, for the record.</source>
        <translation>Gliderens serienummer eller navn, for journalen.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="42"/>
        <source> kg</source>
        <translation> kg</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="43"/>
        <source>Mass of the complete glider in air (wings and ballast as now), from a calibrated scale.</source>
        <translation>Massen til hele glideren i luft (vinger og ballast som nå), fra en kalibrert vekt.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="44"/>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="47"/>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="83"/>
        <source> g</source>
        <translation> g</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="45"/>
        <source>Spring scale hanging directly above the bow ballast bottles, glider fully submerged and still. Read it at eye level, in grams.</source>
        <translation>Fjærvekten som henger rett over baugballastflaskene, glideren helt nedsenket og i ro. Les av i øyehøyde, i gram.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="48"/>
        <source>Spring scale hanging directly above the aft ballast bottles, read at the same time.</source>
        <translation>Fjærvekten som henger rett over akterballastflaskene, lest av samtidig.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="49"/>
        <source>Glider and spring scales</source>
        <translation>Glider og fjærvekter</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="51"/>
        <source>Gl&amp;ider:</source>
        <translation>Gl&amp;ider:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="52"/>
        <source>&amp;Dry mass:</source>
        <translation>&amp;Tørrmasse:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="53"/>
        <source>Bow s&amp;cale:</source>
        <translation>&amp;Baugvekt:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="54"/>
        <source>&amp;Aft scale:</source>
        <translation>&amp;Aktervekt:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="58"/>
        <source>Fresh water</source>
        <translation>Ferskvann</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="59"/>
        <source>Salt water</source>
        <translation>Saltvann</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="60"/>
        <source>Fresh tank water is taken as 1000 kg/m³ unless you measured it; salt water needs its measured density.</source>
        <translation>Ferskt tankvann regnes som 1000 kg/m³ hvis du ikke har målt det; saltvann krever målt tetthet.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="63"/>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="67"/>
        <source> kg/m³</source>
        <translation> kg/m³</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="64"/>
        <source>Density of the tank water (hydrometer or CTD).</source>
        <translation>Tettheten til tankvannet (hydrometer eller CTD).</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="65"/>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="69"/>
        <source> °C</source>
        <translation> °C</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="66"/>
        <source>Tank water temperature next to the glider, at mid depth.</source>
        <translation>Tankvannets temperatur ved glideren, på halvt dyp.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="68"/>
        <source>Density of the water the glider will fly in (from a CTD cast or the area&apos;s climatology).</source>
        <translation>Tettheten til vannet glideren skal gå i (fra en CTD-profil eller områdets klimatologi).</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="70"/>
        <source>Temperature of the deployment water: the aluminium hull shrinks in cold water.</source>
        <translation>Temperaturen i utsettingsvannet: aluminiumsskroget krymper i kaldt vann.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="71"/>
        <source>Water</source>
        <translation>Vann</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="73"/>
        <source>Tank &amp;water:</source>
        <translation>Tank&amp;vann:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="74"/>
        <source>Tank d&amp;ensity:</source>
        <translation>Tank&amp;tetthet:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="75"/>
        <source>Tank te&amp;mperature:</source>
        <translation>Tank&amp;temperatur:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="76"/>
        <source>Ta&amp;rget density:</source>
        <translation>&amp;Måltetthet:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="77"/>
        <source>Tar&amp;get temperature:</source>
        <translation>Mål&amp;temperatur:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="79"/>
        <source>Ballast in the glider now</source>
        <translation>Ballast i glideren nå</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="84"/>
        <source>Lead shot in this ballast bottle now, in grams (weigh the bottle contents).</source>
        <translation>Blyhagl i denne ballastflasken nå, i gram (vei innholdet i flasken).</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="85"/>
        <source>Brass in this wing rail now, in grams.</source>
        <translation>Messing i denne vingeskinnen nå, i gram.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="169"/>
        <source>In the tank it displaces &lt;b&gt;%1 kg&lt;/b&gt;; in the target water it is neutral at &lt;b&gt;%2 kg&lt;/b&gt;. It weighs %3 kg, so it is &lt;b&gt;%4 %5&lt;/b&gt;.&lt;br&gt;Tank step: %6.&lt;br&gt;With that done, the bow scale should read &lt;b&gt;%7 g&lt;/b&gt; and the aft scale &lt;b&gt;%8 g&lt;/b&gt;.</source>
        <translation>I tanken fortrenger den &lt;b&gt;%1 kg&lt;/b&gt;; i målvannet er den nøytral ved &lt;b&gt;%2 kg&lt;/b&gt;. Den veier %3 kg, så den er &lt;b&gt;%4 %5&lt;/b&gt;.&lt;br&gt;Tanktrinn: %6.&lt;br&gt;Når det er gjort, skal baugvekten vise &lt;b&gt;%7 g&lt;/b&gt; og aktervekten &lt;b&gt;%8 g&lt;/b&gt;.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="176"/>
        <source>g heavy</source>
        <translation>g for tung</translation>
    </message>
    <message>
        <location filename="../../ui/pages/tank_weighing_page.cpp" line="176"/>
        <source>g light</source>
        <translation>g for lett</translation>
    </message>
</context>
<context>
    <name>auv::ui::VehiclePage</name>
    <message>
        <location filename="../../ui/pages/vehicle_page.cpp" line="31"/>
        <source>Vehicle and configuration</source>
        <translation>Fartøy og konfigurasjon</translation>
    </message>
    <message>
        <location filename="../../ui/pages/vehicle_page.cpp" line="32"/>
        <source>Choose the vehicle and name the payload configuration you are ballasting.</source>
        <translation>Velg fartøy og gi nyttelastkonfigurasjonen du ballasterer et navn.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/vehicle_page.cpp" line="35"/>
        <source>The vehicle profile: hull volume, centre of buoyancy, adjustment points and weight kit.</source>
        <translation>Fartøyprofilen: skrogvolum, oppdriftssenter, trimpunkter og vektsett.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/vehicle_page.cpp" line="48"/>
        <source>Configuration ID as on the vehicle&apos;s ballasting sheet: three groups of letters or digits, e.g. 01-02-03 (vehicle, payload set, water).</source>
        <translation>Konfigurasjons-ID som på fartøyets ballastskjema: tre grupper bokstaver eller sifre, f.eks. 01-02-03 (fartøy, nyttelastsett, vann).</translation>
    </message>
    <message>
        <location filename="../../ui/pages/vehicle_page.cpp" line="50"/>
        <source>e.g. 01-02-03</source>
        <translation>f.eks. 01-02-03</translation>
    </message>
    <message>
        <location filename="../../ui/pages/vehicle_page.cpp" line="51"/>
        <source>Which payload modules are fitted, in your words.</source>
        <translation>Hvilke nyttelastmoduler som er montert, med dine ord.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/vehicle_page.cpp" line="52"/>
        <source>Area of operation, e.g. the fjord or the survey site.</source>
        <translation>Operasjonsområde, f.eks. fjorden eller kartleggingsfeltet.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/vehicle_page.cpp" line="53"/>
        <source>Kind of water, e.g. fjord, coastal, open ocean.</source>
        <translation>Type vann, f.eks. fjord, kyst, åpent hav.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/vehicle_page.cpp" line="72"/>
        <source>&amp;Vehicle:</source>
        <translation>&amp;Fartøy:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/vehicle_page.cpp" line="73"/>
        <source>&amp;Configuration ID:</source>
        <translation>&amp;Konfigurasjons-ID:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/vehicle_page.cpp" line="75"/>
        <source>&amp;Payload:</source>
        <translation>&amp;Nyttelast:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/vehicle_page.cpp" line="76"/>
        <source>&amp;Area:</source>
        <translation>&amp;Område:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/vehicle_page.cpp" line="77"/>
        <source>Water &amp;type:</source>
        <translation>Vann&amp;type:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/vehicle_page.cpp" line="108"/>
        <source>From the history.</source>
        <translation>Fra historikken.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/vehicle_page.cpp" line="111"/>
        <source>Three groups of 1-8 letters or digits separated by &apos;-&apos;, e.g. 01-02-03.</source>
        <translation>Tre grupper med 1-8 bokstaver eller sifre atskilt med «-», f.eks. 01-02-03.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/vehicle_page.cpp" line="114"/>
        <source>A new configuration ID.</source>
        <translation>En ny konfigurasjons-ID.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/vehicle_page.cpp" line="121"/>
        <source>%1: %2 kg in air, hull volume %3 m³, %4 adjustment points; weighed by %5.</source>
        <translation>%1: %2 kg i luft, skrogvolum %3 m³, %4 trimpunkter; veies med %5.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/vehicle_page.cpp" line="126"/>
        <source>the tank method (spring scales)</source>
        <translation>tankmetoden (fjærvekter)</translation>
    </message>
    <message>
        <location filename="../../ui/pages/vehicle_page.cpp" line="126"/>
        <source>crane scales</source>
        <translation>kranvekter</translation>
    </message>
    <message>
        <location filename="../../ui/pages/vehicle_page.cpp" line="54"/>
        <source>mm</source>
        <translation>mm</translation>
    </message>
    <message>
        <location filename="../../ui/pages/vehicle_page.cpp" line="58"/>
        <source>not measured</source>
        <translation>ikke målt</translation>
    </message>
    <message>
        <location filename="../../ui/pages/vehicle_page.cpp" line="60"/>
        <source>How far the centre of gravity is below the centre of buoyancy, from an inclining or roll test. With it the analysis finds the sideways CG offset and the roll from the log; without it they stay not known. Leave empty when not measured.</source>
        <translation>Hvor langt tyngdepunktet ligger under oppdriftssenteret, fra en krengeprøve eller rulleprøve. Med den finner analysen tyngdepunktets sideforskyvning og rullingen fra loggen; uten den forblir de ikke kjent. La feltet stå tomt når den ikke er målt.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/vehicle_page.cpp" line="78"/>
        <source>B&amp;G (CG below CB):</source>
        <translation>B&amp;G (CG under CB):</translation>
    </message>
</context>
<context>
    <name>auv::ui::WaterPage</name>
    <message>
        <location filename="../../ui/pages/water_page.cpp" line="21"/>
        <source>Fresh water (about 0.5)</source>
        <translation>Ferskvann (ca. 0,5)</translation>
    </message>
    <message>
        <location filename="../../ui/pages/water_page.cpp" line="22"/>
        <source>Brackish, mildly (1-5)</source>
        <translation>Svakt brakkvann (1-5)</translation>
    </message>
    <message>
        <location filename="../../ui/pages/water_page.cpp" line="23"/>
        <source>Brackish, moderately (5-15)</source>
        <translation>Moderat brakkvann (5-15)</translation>
    </message>
    <message>
        <location filename="../../ui/pages/water_page.cpp" line="24"/>
        <source>Brackish, heavily (15-30)</source>
        <translation>Sterkt brakkvann (15-30)</translation>
    </message>
    <message>
        <location filename="../../ui/pages/water_page.cpp" line="25"/>
        <source>Sea water (about 35)</source>
        <translation>Sjøvann (ca. 35)</translation>
    </message>
    <message>
        <location filename="../../ui/pages/water_page.cpp" line="31"/>
        <source>Mission water</source>
        <translation>Oppdragsvann</translation>
    </message>
    <message>
        <location filename="../../ui/pages/water_page.cpp" line="32"/>
        <source>Where will the vehicle fly? Density includes pressure at the operating depth.</source>
        <translation>Hvor skal fartøyet gå? Tettheten tar med trykket på operasjonsdybden.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/water_page.cpp" line="34"/>
        <source>Water temperature at the operating depth if you know it (CTD cast), else at the surface.</source>
        <translation>Vanntemperatur på operasjonsdybden hvis du kjenner den (CTD-profil), ellers i overflaten.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/water_page.cpp" line="37"/>
        <source>Measured salinity</source>
        <translation>Målt saltholdighet</translation>
    </message>
    <message>
        <location filename="../../ui/pages/water_page.cpp" line="39"/>
        <source>Pick a water type if you have no salinity measurement (thesis Table 2.1).</source>
        <translation>Velg en vanntype hvis du ikke har målt saltholdigheten (avhandlingen tabell 2.1).</translation>
    </message>
    <message>
        <location filename="../../ui/pages/water_page.cpp" line="41"/>
        <source>Practical salinity of the mission water.</source>
        <translation>Praktisk saltholdighet i oppdragsvannet.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/water_page.cpp" line="42"/>
        <source>Depth where the vehicle spends most of the mission.</source>
        <translation>Dybden der fartøyet er mesteparten av oppdraget.</translation>
    </message>
    <message>
        <location filename="../../ui/pages/water_page.cpp" line="43"/>
        <source>Latitude of the area (gravity for depth to pressure).</source>
        <translation>Områdets breddegrad (tyngdekraft for dybde til trykk).</translation>
    </message>
    <message>
        <location filename="../../ui/pages/water_page.cpp" line="50"/>
        <source>&amp;Temperature:</source>
        <translation>&amp;Temperatur:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/water_page.cpp" line="51"/>
        <source>Water t&amp;ype:</source>
        <translation>Vann&amp;type:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/water_page.cpp" line="52"/>
        <source>&amp;Salinity:</source>
        <translation>&amp;Saltholdighet:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/water_page.cpp" line="53"/>
        <source>Operating &amp;depth:</source>
        <translation>Operasjons&amp;dybde:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/water_page.cpp" line="54"/>
        <source>&amp;Latitude:</source>
        <translation>&amp;Breddegrad:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/water_page.cpp" line="55"/>
        <source>In-situ density:</source>
        <translation>Tetthet in situ:</translation>
    </message>
    <message>
        <location filename="../../ui/pages/water_page.cpp" line="82"/>
        <source>%1 kg/m³ at %2 dbar</source>
        <translation>%1 kg/m³ ved %2 dbar</translation>
    </message>
</context>
<context>
    <name>auv::ui::WeightMapWidget</name>
    <message>
        <location filename="../../ui/widgets/weight_map_widget.cpp" line="16"/>
        <source>Top view, bow to the right. Green: add, red: remove, grey: installed now.</source>
        <translation>Sett ovenfra, baugen til høyre. Grønn: legg til, rød: fjern, grå: montert nå.</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/weight_map_widget.cpp" line="129"/>
        <source>bow ▶</source>
        <translation>baug ▶</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/weight_map_widget.cpp" line="129"/>
        <source>starboard ▼</source>
        <translation>styrbord ▼</translation>
    </message>
    <message>
        <location filename="../../ui/widgets/weight_map_widget.cpp" line="158"/>
        <source>CB</source>
        <translation>CB</translation>
    </message>
</context>
<context>
    <name>auv::ui::WorkOrder</name>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="39"/>
        <source>add %1 × %2</source>
        <translation>legg til %1 × %2</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="39"/>
        <source>remove %1 × %2</source>
        <translation>fjern %1 × %2</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="41"/>
        <source>no change</source>
        <translation>ingen endring</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="44"/>
        <source>✓ in band</source>
        <translation>✓ innenfor båndet</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="44"/>
        <source>✗ outside the band</source>
        <translation>✗ utenfor båndet</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="139"/>
        <location filename="../../ui/wizard/glider_work_order.cpp" line="141"/>
        <source>Ballast work order</source>
        <translation>Arbeidsordre for ballast</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="50"/>
        <location filename="../../ui/wizard/glider_work_order.cpp" line="142"/>
        <source>Vehicle: %1 (%2)</source>
        <translation>Fartøy: %1 (%2)</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="51"/>
        <location filename="../../ui/wizard/glider_work_order.cpp" line="142"/>
        <source>Configuration: %1</source>
        <translation>Konfigurasjon: %1</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="52"/>
        <location filename="../../ui/wizard/glider_work_order.cpp" line="143"/>
        <source>Date: %1</source>
        <translation>Dato: %1</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="56"/>
        <source>Payload: %1; area: %2</source>
        <translation>Nyttelast: %1; område: %2</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="56"/>
        <source>not given</source>
        <translation>ikke oppgitt</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="83"/>
        <source>%1 g</source>
        <translation>%1 g</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="84"/>
        <source>%1 kg</source>
        <translation>%1 kg</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="87"/>
        <source>Ballast work order: first mission</source>
        <translation>Ballastarbeidsordre: første oppdrag</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="89"/>
        <source>From: the tank weighing</source>
        <translation>Fra: tankveiingen</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="89"/>
        <source>From: the crane weighing</source>
        <translation>Fra: kranveiingen</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="90"/>
        <source>Water the vehicle is balanced for</source>
        <translation>Vannet fartøyet er balansert for</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="92"/>
        <source>Target water: density %1 kg/m³ at %2 °C</source>
        <translation>Målvann: tetthet %1 kg/m³ ved %2 °C</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="95"/>
        <source>%1 °C, %2 PSU at %3 m: density %4 kg/m³</source>
        <translation>%1 °C, %2 PSU på %3 m: tetthet %4 kg/m³</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="100"/>
        <source>Weighed %1 kg, buoyancy %2 kg: net buoyancy %3 before the change (positive = light)</source>
        <translation>Veid %1 kg, oppdrift %2 kg: netto oppdrift %3 før endringen (positiv = lett)</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="116"/>
        <source>After the change, in the water above:</source>
        <translation>Etter endringen, i vannet ovenfor:</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="117"/>
        <source>Net buoyancy %1 (band %2 .. %3): %4</source>
        <translation>Netto oppdrift %1 (bånd %2 .. %3): %4</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="120"/>
        <source>Pitch at rest %1° (band ±%2°): %3</source>
        <translation>Stamp i ro %1° (bånd ±%2°): %3</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="123"/>
        <source>Roll %1° (band ±%2°): %3</source>
        <translation>Rull %1° (bånd ±%2°): %3</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="142"/>
        <source>Plan: %1 policy, from %2</source>
        <translation>Plan: strategi %1, fra %2</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="145"/>
        <source>Operating depth %1 m: %2 °C, %3 PSU, in-situ density %4 kg/m³ (%5)</source>
        <translation>Operasjonsdybde %1 m: %2 °C, %3 PSU, in situ-tetthet %4 kg/m³ (%5)</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="150"/>
        <source>entered by the operator</source>
        <translation>skrevet inn av operatøren</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="150"/>
        <source>last mission&apos;s CTD</source>
        <translation>siste oppdrags CTD</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="153"/>
        <source>%1 m (%2)</source>
        <translation>%1 m (%2)</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="155"/>
        <source>Must also stay light at: %1</source>
        <translation>Må også holde seg lett på: %1</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="62"/>
        <source>Point</source>
        <translation>Punkt</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="62"/>
        <source>Now</source>
        <translation>Nå</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="62"/>
        <source>Change</source>
        <translation>Endring</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="63"/>
        <source>Pieces</source>
        <translation>Vektbiter</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="63"/>
        <source>After</source>
        <translation>Etter</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="63"/>
        <location filename="../../ui/wizard/glider_work_order.cpp" line="148"/>
        <source>Done</source>
        <translation>Gjort</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="165"/>
        <source> (plan %1)</source>
        <translation> (plan %1)</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="176"/>
        <source>As actually installed, at %1 m:</source>
        <translation>Slik det faktisk er montert, på %1 m:</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="176"/>
        <source>As planned, at %1 m:</source>
        <translation>Som planlagt, på %1 m:</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="177"/>
        <source>Net buoyancy %1 ± %2 kg (band %3 .. %4 kg): %5</source>
        <translation>Netto oppdrift %1 ± %2 kg (bånd %3 .. %4 kg): %5</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="184"/>
        <source>Pitch in flight at %1 m/s %2° (band ±%3°): %4</source>
        <translation>Stamp under fart ved %1 m/s %2° (bånd ±%3°): %4</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="188"/>
        <source>Pitch in flight: not predicted (no hydrodynamics or cruise speed)</source>
        <translation>Stamp under fart: ikke beregnet (mangler hydrodynamikk eller marsjfart)</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="192"/>
        <source>Safe: at least %1 kg light (1.645 σ) at every planned depth.</source>
        <translation>Sikkert: minst %1 kg lett (1,645 σ) på hver planlagte dybde.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="193"/>
        <source>NOT SAFE: less than %1 kg light (1.645 σ) at a planned depth.</source>
        <translation>IKKE SIKKERT: mindre enn %1 kg lett (1,645 σ) på en planlagt dybde.</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="128"/>
        <location filename="../../ui/wizard/work_order.cpp" line="202"/>
        <location filename="../../ui/wizard/glider_work_order.cpp" line="190"/>
        <source>Done by: ______________________   Signature: ______________________   Date: ____________</source>
        <translation>Utført av: ______________________   Signatur: ______________________   Dato: ____________</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="141"/>
        <location filename="../../ui/wizard/glider_work_order.cpp" line="145"/>
        <source>Next mission&apos;s water</source>
        <translation>Vannet i neste oppdrag</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="274"/>
        <source>What to change</source>
        <translation>Hva som skal endres</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="243"/>
        <source>Expected result</source>
        <translation>Forventet resultat</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="247"/>
        <source>Warnings</source>
        <translation>Advarsler</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="248"/>
        <source>⚠ %1</source>
        <translation>⚠ %1</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="262"/>
        <source>Steps and notes</source>
        <translation>Trinn og merknader</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="331"/>
        <source>Where (top view, bow to the right)</source>
        <translation>Hvor (sett ovenfra, baugen til høyre)</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="363"/>
        <location filename="../../ui/wizard/work_order.cpp" line="367"/>
        <location filename="../../ui/wizard/work_order.cpp" line="392"/>
        <source>cannot write %1: check the folder and its permissions</source>
        <translation>kan ikke skrive %1: sjekk mappen og tilgangene</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="181"/>
        <source>Pitch at rest %1 (band ±%2°)%3</source>
        <translation>Stamp i ro %1 (bånd ±%2°)%3</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="189"/>
        <source>Roll %1 (band ±%2°)%3</source>
        <translation>Rull %1 (bånd ±%2°)%3</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="252"/>
        <source>What was calibrated</source>
        <translation>Hva som ble kalibrert</translation>
    </message>
    <message>
        <location filename="../../ui/wizard/work_order.cpp" line="257"/>
        <source>Calibration manoeuvre for the next mission</source>
        <translation>Kalibreringsmanøver for neste oppdrag</translation>
    </message>
</context>
</TS>
