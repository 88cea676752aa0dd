<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="fr">
<context>
    <name>QAbstractFileIconProvider</name>
    <message>
        <source>Drive</source>
        <translation>Disque</translation>
    </message>
    <message>
        <source>Unknown</source>
        <translation>Inconnu</translation>
    </message>
    <message>
        <source>Folder</source>
        <comment>All other platforms</comment>
        <translation>Dossier</translation>
    </message>
    <message>
        <source>Shortcut</source>
        <comment>All other platforms</comment>
        <translation>Raccourci</translation>
    </message>
</context>
<context>
    <name>QFileDialog</name>
    <message>
        <source>Look in:</source>
        <translation>Voir dans :</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Précédent</translation>
    </message>
    <message>
        <source>Go back</source>
        <translation>Aller à l&apos;élément précédent</translation>
    </message>
    <message>
        <source>Forward</source>
        <translation>Suivant</translation>
    </message>
    <message>
        <source>Go forward</source>
        <translation>Va à l&apos;élément suivant</translation>
    </message>
    <message>
        <source>Parent Directory</source>
        <translation>Dossier parent</translation>
    </message>
    <message>
        <source>Go to the parent directory</source>
        <translation>Va au dossier parent</translation>
    </message>
    <message>
        <source>Create New Folder</source>
        <translation>Créer un nouveau dossier</translation>
    </message>
    <message>
        <source>Create a New Folder</source>
        <translation>Crée un nouveau dossier</translation>
    </message>
    <message>
        <source>List View</source>
        <translation>Vue en liste</translation>
    </message>
    <message>
        <source>Change to list view mode</source>
        <translation>Affiche la vue sous forme de liste</translation>
    </message>
    <message>
        <source>Detail View</source>
        <translation>Vue détaillée</translation>
    </message>
    <message>
        <source>Change to detail view mode</source>
        <translation>Affiche la vue sous forme détaillée</translation>
    </message>
    <message>
        <source>Sidebar</source>
        <translation>Barre latérale</translation>
    </message>
    <message>
        <source>List of places and bookmarks</source>
        <translation>Liste des emplacements et des favoris</translation>
    </message>
    <message>
        <source>Files</source>
        <translation>Fichiers</translation>
    </message>
    <message>
        <source>File &amp;name:</source>
        <translation>&amp;Nom de fichier :</translation>
    </message>
    <message>
        <source>Files of type:</source>
        <translation>Fichiers de type :</translation>
    </message>
    <message>
        <source>&amp;Open</source>
        <translation>&amp;Ouvrir</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Enregistrer</translation>
    </message>
    <message>
        <source>&amp;Choose</source>
        <translation>&amp;Choisir</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>Ouvrir</translation>
    </message>
    <message>
        <source>Save As</source>
        <translation>Enregistrer sous</translation>
    </message>
    <message>
        <source>All Files (*)</source>
        <translation>Tous les fichiers (*)</translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation>Tous les fichiers (*)</translation>
    </message>
    <message>
        <source>Directory:</source>
        <translation>Dossier :</translation>
    </message>
    <message>
        <source>Directories</source>
        <translation>Dossiers</translation>
    </message>
    <message>
        <source>Find Directory</source>
        <translation>Chercher dans le dossier</translation>
    </message>
    <message>
        <source>File</source>
        <translation>Fichier</translation>
    </message>
    <message>
        <source>File Folder</source>
        <translation>Dossier</translation>
    </message>
    <message>
        <source>Folder</source>
        <translation>Dossier</translation>
    </message>
    <message>
        <source>%1 File</source>
        <translation>Fichier %1</translation>
    </message>
    <message>
        <source>Unknown</source>
        <translation>Inconnu</translation>
    </message>
    <message>
        <source>New Folder</source>
        <translation>Nouveau dossier</translation>
    </message>
    <message>
        <source>&amp;New Folder</source>
        <translation>&amp;Nouveau dossier</translation>
    </message>
    <message>
        <source>&amp;Rename</source>
        <translation>&amp;Renommer</translation>
    </message>
    <message>
        <source>&amp;Delete</source>
        <translation>Suppri&amp;mer</translation>
    </message>
    <message>
        <source>Show &amp;hidden files</source>
        <translation>Afficher les fic&amp;hiers cachés</translation>
    </message>
    <message>
        <source>Recent Places</source>
        <translation>Emplacements récents</translation>
    </message>
    <message>
        <source>My Computer</source>
        <translation>Poste de travail</translation>
    </message>
    <message>
        <source>%1 already exists.
Do you want to replace it?</source>
        <translation>Le fichier %1 existe déjà.
Voulez-vous l&apos;écraser ?</translation>
    </message>
    <message>
        <source>%1
File not found.
Please verify the correct file name was given.</source>
        <translation>%1
Fichier introuvable.
Veuillez vérifier que le nom du fichier est correct.</translation>
    </message>
    <message>
        <source>%1
Directory not found.
Please verify the correct directory name was given.</source>
        <translation>%1
Dossier introuvable.
Veuillez vérifier que le nom du dossier est correct.</translation>
    </message>
    <message>
        <source>Are you sure you want to delete &apos;%1&apos;?</source>
        <translation>Êtes-vous sûr de vouloir supprimer &quot;%1&quot; ?</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is write protected.
Do you want to delete it anyway?</source>
        <translation>&quot;%1&quot; est protégé en écriture.
Voulez-vous quand même le supprimer ?</translation>
    </message>
    <message>
        <source>Could not delete directory.</source>
        <translation>Impossible de supprimer le dossier.</translation>
    </message>
</context>
<context>
    <name>QFileSystemModel</name>
    <message>
        <source>Name</source>
        <translation>Nom</translation>
    </message>
    <message>
        <source>Size</source>
        <translation>Taille</translation>
    </message>
    <message>
        <source>Type</source>
        <translation>Type</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Type</translation>
    </message>
    <message>
        <source>Date Modified</source>
        <translation>Dernière modification</translation>
    </message>
    <message>
        <source>Computer</source>
        <translation>Ordinateur</translation>
    </message>
    <message>
        <source>My Computer</source>
        <translation>Poste de travail</translation>
    </message>
    <message>
        <source>Invalid filename</source>
        <translation>Nom de fichier invalide</translation>
    </message>
</context>
<context>
    <name>QPlatformTheme</name>
    <message>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <source>Save</source>
        <translation>Enregistrer</translation>
    </message>
    <message>
        <source>Save All</source>
        <translation>Tout enregistrer</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>Ouvrir</translation>
    </message>
    <message>
        <source>&amp;Yes</source>
        <translation>&amp;Oui</translation>
    </message>
    <message>
        <source>Yes to &amp;All</source>
        <translation>Oui à &amp;tout</translation>
    </message>
    <message>
        <source>&amp;No</source>
        <translation>&amp;Non</translation>
    </message>
    <message>
        <source>N&amp;o to All</source>
        <translation>N&amp;on à tout</translation>
    </message>
    <message>
        <source>Abort</source>
        <translation>Interrompre</translation>
    </message>
    <message>
        <source>Retry</source>
        <translation>Réessayer</translation>
    </message>
    <message>
        <source>Ignore</source>
        <translation>Ignorer</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Fermer</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Annuler</translation>
    </message>
    <message>
        <source>Discard</source>
        <translation>Ne pas enregistrer</translation>
    </message>
    <message>
        <source>Help</source>
        <translation>Aide</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Appliquer</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Réinitialiser</translation>
    </message>
    <message>
        <source>Restore Defaults</source>
        <translation>Valeurs par défaut</translation>
    </message>
</context>
<context>
    <name>stylos::app::AnnotationActions</name>
    <message>
        <source>The legend has no class in this layer: add one first</source>
        <translation>La légende n’a aucune classe dans cette couche : ajoutez-en une d’abord</translation>
    </message>
    <message>
        <source>Erase with the lasso</source>
        <translation>Effacer au lasso</translation>
    </message>
    <message>
        <source>Lasso in 3D</source>
        <translation>Lasso en 3D</translation>
    </message>
    <message>
        <source>Lasso: no fragment selected or under the lasso</source>
        <translation>Lasso : aucun fragment sélectionné ni sous le lasso</translation>
    </message>
    <message>
        <source>Lasso: no visible cell changed</source>
        <translation>Lasso : aucune cellule visible n’a changé</translation>
    </message>
    <message>
        <source>Annotate in 3D (&amp;lasso)</source>
        <translation>Annoter en 3D (&amp;lasso)</translation>
    </message>
    <message>
        <source>Draw a lasso in the 3D view: the visible cells of the selected fragment inside it take the chosen class; Ctrl erases; Escape cancels; Alt-drag orbits</source>
        <translation>Tracez un lasso dans la vue 3D : les cellules visibles du fragment sélectionné à l’intérieur prennent la classe choisie ; Ctrl efface ; Échap annule ; Alt-glisser fait tourner la vue</translation>
    </message>
    <message>
        <source>&amp;Erase with the lasso</source>
        <translation>&amp;Effacer au lasso</translation>
    </message>
    <message>
        <source>The lasso removes the class of the cells it takes</source>
        <translation>Le lasso retire la classe des cellules qu’il prend</translation>
    </message>
    <message>
        <source>The class the lasso gives</source>
        <translation>La classe que donne le lasso</translation>
    </message>
    <message>
        <source>&amp;Material / condition layer</source>
        <translation>Couche &amp;matériau / état</translation>
    </message>
    <message>
        <source>&amp;Tool mark layer</source>
        <translation>Couche &amp;traces d’outil</translation>
    </message>
    <message>
        <source>3D lasso</source>
        <comment>toolbar</comment>
        <translation>Lasso 3D</translation>
    </message>
    <message>
        <source>Erase</source>
        <comment>toolbar</comment>
        <translation>Effacer</translation>
    </message>
    <message>
        <source>Lasso: the selected fragment is hidden; show it to annotate it in 3D</source>
        <translation>Lasso : le fragment sélectionné est masqué ; affichez-le pour l’annoter en 3D</translation>
    </message>
</context>
<context>
    <name>stylos::app::AssemblyActions</name>
    <message>
        <source>Assembly %1</source>
        <translation>Assemblage %1</translation>
    </message>
    <message numerus="yes">
        <source>%1: %n fragment(s)</source>
        <translation>
            <numerusform>%1 : %n fragment</numerusform>
            <numerusform>%1 : %n fragments</numerusform>
        </translation>
    </message>
    <message>
        <source>New &amp;assembly from selection</source>
        <translation>Nouvel &amp;assemblage depuis la sélection</translation>
    </message>
    <message>
        <source>Group the selected fragments into an assembly that moves as one; a drum among them (a fragment with an axis guide) becomes what they dock against</source>
        <translation>Regrouper les fragments sélectionnés en un assemblage qui se déplace d’un bloc ; un tambour parmi eux (un fragment avec un guide d’axe) devient celui contre lequel ils s’amarrent</translation>
    </message>
    <message>
        <source>&amp;Take out of assembly</source>
        <translation>&amp;Sortir de l’assemblage</translation>
    </message>
    <message>
        <source>Move the selected fragments back to the top of the scene, where they are</source>
        <translation>Remettre les fragments sélectionnés au premier niveau de la scène, là où ils sont</translation>
    </message>
    <message>
        <source>&amp;Remove assembly</source>
        <translation>&amp;Dissoudre l’assemblage</translation>
    </message>
    <message>
        <source>Dissolve the selected assembly; its fragments stay where they are</source>
        <translation>Dissoudre l’assemblage sélectionné ; ses fragments restent où ils sont</translation>
    </message>
    <message>
        <source>&amp;Use as the assembly&apos;s drum</source>
        <translation>&amp;Utiliser comme tambour de l’assemblage</translation>
    </message>
    <message>
        <source>Dock the assembly&apos;s fragments against the guides of the selected fragment</source>
        <translation>Amarrer les fragments de l’assemblage contre les guides du fragment sélectionné</translation>
    </message>
    <message>
        <source>Dé&amp;veloppée of the assembly</source>
        <translation>Dé&amp;veloppée de l’assemblage</translation>
    </message>
    <message>
        <source>Unroll the assembly&apos;s drum with every fragment of the assembly at its place, on the drum&apos;s axis: the reconstruction in 2D, the free places; click a fragment to select it</source>
        <translation>Dérouler le tambour de l’assemblage avec chaque fragment de l’assemblage à sa place, sur l’axe du tambour : la reconstruction en 2D, les places libres ; cliquer sur un fragment le sélectionne</translation>
    </message>
</context>
<context>
    <name>stylos::app::Automation</name>
    <message>
        <source>Demo drum (%1): A, développée under the skydome, material and condition in colour; B, front view lit from the viewer, the same classes as black-and-white hatches. Generated scan; the painted regions are an illustration.</source>
        <translation>Tambour de démonstration (%1) : A, développée sous le skydome, matériau et état en couleur ; B, vue de face éclairée depuis l’observateur, les mêmes classes en hachures noir et blanc. Relevé généré ; les régions peintes sont une illustration.</translation>
    </message>
</context>
<context>
    <name>stylos::app::CommandLine</name>
    <message>
        <source>Stylos, a workbench for very large 3D scans of monuments. With no file, opens the demo scene.</source>
        <translation>Stylos, un atelier pour les très grands relevés 3D de monuments. Sans fichier, ouvre la scène de démonstration.</translation>
    </message>
    <message>
        <source>file</source>
        <translation>fichier</translation>
    </message>
    <message>
        <source>Wait until the scene and its tasks are ready and the view is refined, save the window as a PNG image to &lt;file&gt; and exit (status 1 if something failed).</source>
        <translation>Attendre que la scène et ses tâches soient prêtes et que la vue soit affinée, enregistrer la fenêtre en image PNG dans &lt;fichier&gt; et quitter (code de sortie 1 en cas d’échec).</translation>
    </message>
    <message>
        <source>Orbit the camera for &lt;frames&gt; frames at 1280 × 800 once the scene is ready, print the frame times as JSON and exit.</source>
        <translation>Faire orbiter la caméra pendant &lt;images&gt; images en 1280 × 800 une fois la scène prête, afficher les temps d’image en JSON et quitter.</translation>
    </message>
    <message>
        <source>frames</source>
        <translation>images</translation>
    </message>
    <message>
        <source>A project (.stylos), or scans to import (%1).</source>
        <translation>Un projet (.stylos), ou des relevés à importer (%1).</translation>
    </message>
    <message>
        <source>--orbit-benchmark: &apos;%1&apos; is not a frame count (1 to 100000)</source>
        <translation>--orbit-benchmark : « %1 » n’est pas un nombre d’images (de 1 à 100000)</translation>
    </message>
    <message>
        <source>--orbit-benchmark needs exactly one file</source>
        <translation>--orbit-benchmark demande exactement un fichier</translation>
    </message>
    <message>
        <source>--grab and --orbit-benchmark do not go together</source>
        <translation>--grab et --orbit-benchmark ne peuvent pas être combinés</translation>
    </message>
    <message>
        <source>Turn the first fragment, a change of its pose every frame, for &lt;frames&gt; frames at 1280 × 800 once the scene is ready, print the frame times as JSON and exit.</source>
        <translation>Faire tourner le premier fragment, un changement de sa pose à chaque image, pendant &lt;images&gt; images en 1280 × 800 une fois la scène prête, afficher les temps d’image en JSON et quitter.</translation>
    </message>
    <message>
        <source>--pose-benchmark: &apos;%1&apos; is not a frame count (1 to 100000)</source>
        <translation>--pose-benchmark : « %1 » n’est pas un nombre d’images (de 1 à 100000)</translation>
    </message>
    <message>
        <source>--pose-benchmark needs exactly one file</source>
        <translation>--pose-benchmark demande exactement un fichier</translation>
    </message>
    <message>
        <source>--pose-benchmark goes with neither --grab nor --orbit-benchmark</source>
        <translation>--pose-benchmark ne peut être combiné ni avec --grab ni avec --orbit-benchmark</translation>
    </message>
    <message>
        <source>With --grab: first fit the first fragment&apos;s drum guides, dock against it and show the Move tool on the second fragment, in the drum&apos;s frame.</source>
        <translation>Avec --grab : ajuster d’abord les guides de tambour du premier fragment, s’y amarrer et montrer l’outil Déplacer sur le second fragment, dans le repère du tambour.</translation>
    </message>
    <message>
        <source>--gizmo goes with --grab</source>
        <translation>--gizmo s’utilise avec --grab</translation>
    </message>
    <message>
        <source>With --grab: first fit the first fragment&apos;s drum guides, dock the second fragment to its flutes from where it stands and show its contact readout.</source>
        <translation>Avec --grab : ajuster d’abord les guides de tambour du premier fragment, amarrer le second fragment à ses cannelures depuis sa position et afficher son relevé de contact.</translation>
    </message>
    <message>
        <source>--dock goes with --grab</source>
        <translation>--dock s’emploie avec --grab</translation>
    </message>
    <message>
        <source>--dock and --gizmo do not go together</source>
        <translation>--dock et --gizmo ne vont pas ensemble</translation>
    </message>
    <message>
        <source>With --grab: first label three regions of the first fragment with the 3D lasso (preserved marble, fractured marble, plaster) and show the Annotation shading.</source>
        <translation>Avec --grab : étiqueter d’abord trois régions du premier fragment au lasso 3D (marbre conservé, marbre fracturé, plâtre) et afficher l’ombrage Annotation.</translation>
    </message>
    <message>
        <source>--annotation goes with --grab alone</source>
        <translation>--annotation va avec --grab seul</translation>
    </message>
    <message>
        <source>--paint goes with --grab</source>
        <translation>--paint s’emploie avec --grab</translation>
    </message>
    <message>
        <source>With --grab: paint as --paint, then write the first fragment&apos;s plate (its développée and front view at 1:N) to BASE.pdf and BASE.png, and grab the Export plate dialog.</source>
        <translation>Avec --grab : peindre comme --paint, puis écrire la planche du premier fragment (sa développée et sa vue de face au 1:N) dans BASE.pdf et BASE.png, et capturer la boîte de dialogue Exporter une planche.</translation>
    </message>
    <message>
        <source>--plate goes with --grab alone</source>
        <translation>--plate va avec --grab seul</translation>
    </message>
    <message>
        <source>With --grab: first compute the first fragment&apos;s développée and paint a few annotation regions on it (marble, fractured marble, plaster; a claw-chisel area in the tool-mark layer). With --dock too: after the dock, the développée of the second fragment&apos;s assembly, painted across the drum and the fragment.</source>
        <translation>Avec --grab : calculer d’abord la développée du premier fragment et y peindre quelques régions d’annotation (marbre, marbre fracturé, plâtre ; une zone de gradine dans la couche des traces d’outil). Avec --dock aussi : après l’accostage, la développée de l’assemblage du deuxième fragment, peinte à travers le tambour et le fragment.</translation>
    </message>
    <message>
        <source>--paint does not go with --gizmo or --annotation</source>
        <translation>--paint ne va pas avec --gizmo ni --annotation</translation>
    </message>
</context>
<context>
    <name>stylos::app::DeveloppeeDock</name>
    <message>
        <source>Développée</source>
        <translation>Développée</translation>
    </message>
</context>
<context>
    <name>stylos::app::DeveloppeeLink</name>
    <message>
        <source>Développée of %1 cancelled</source>
        <translation>Développée de %1 annulée</translation>
    </message>
    <message>
        <source>The développée of %1 needs a drum with an axis guide (Use as the assembly&apos;s drum)</source>
        <translation>La développée de %1 demande un tambour avec un guide d’axe (Utiliser comme tambour de l’assemblage)</translation>
    </message>
    <message>
        <source>The développée of %1 cannot start: its drum is still opening or busy</source>
        <translation>La développée de %1 ne peut pas démarrer : son tambour est encore en ouverture ou occupé</translation>
    </message>
    <message>
        <source>Développée of %1: %2</source>
        <translation>Développée de %1 : %2</translation>
    </message>
    <message>
        <source>%1 is unrolled about its drum&apos;s axis guide and does not stand on the drum yet: dock it first, or untick Use the axis guide to unroll it about a cylinder fitted to itself.</source>
        <translation>%1 est déroulé autour du guide d’axe de son tambour et ne se tient pas encore sur le tambour : amarrez-le d’abord, ou décochez « Utiliser le guide d’axe » pour le dérouler autour d’un cylindre ajusté sur lui-même.</translation>
    </message>
</context>
<context>
    <name>stylos::app::DisplaySettingsWidget</name>
    <message>
        <source>Headlight</source>
        <translation>Éclairage frontal</translation>
    </message>
    <message>
        <source>Skydome</source>
        <translation>Skydome</translation>
    </message>
    <message>
        <source>Scan colour</source>
        <translation>Couleur du relevé</translation>
    </message>
    <message>
        <source> ×</source>
        <translation> ×</translation>
    </message>
    <message>
        <source> M points</source>
        <translation> M points</translation>
    </message>
    <message>
        <source>Points drawn at most; the view refines up to it when the camera stops</source>
        <translation>Nombre maximal de points dessinés ; la vue s’affine jusqu’à ce nombre quand la caméra s’arrête</translation>
    </message>
    <message>
        <source>View-dependent</source>
        <translation>Selon la vue</translation>
    </message>
    <message>
        <source>Global level</source>
        <translation>Niveau global</translation>
    </message>
    <message>
        <source>Shading</source>
        <translation>Ombrage</translation>
    </message>
    <message>
        <source>Splat size</source>
        <translation>Taille des splats</translation>
    </message>
    <message>
        <source>Point budget</source>
        <translation>Budget de points</translation>
    </message>
    <message>
        <source>Level of detail</source>
        <translation>Niveau de détail</translation>
    </message>
    <message>
        <source>Size of the drawn points, as a multiple of the size of their octree cell</source>
        <translation>Taille des points dessinés, en multiple de la taille de leur cellule d’octree</translation>
    </message>
    <message>
        <source>View-dependent: finer cells near the camera, within the point budget; global level: every fragment drawn at the one octree level below</source>
        <translation>Selon la vue : des cellules plus fines près de la caméra, dans la limite du budget de points ; niveau global : chaque fragment dessiné au niveau d’octree choisi ci-dessous</translation>
    </message>
    <message>
        <source>The octree level drawn when the level of detail is global (0: the root cell)</source>
        <translation>Le niveau d’octree dessiné quand le niveau de détail est global (0 : la cellule racine)</translation>
    </message>
    <message>
        <source>Octree level</source>
        <translation>Niveau d’octree</translation>
    </message>
    <message>
        <source>Eye-dome lighting</source>
        <translation>Éclairage eye-dome (EDL)</translation>
    </message>
    <message>
        <source>Annotation</source>
        <translation>Annotation</translation>
    </message>
    <message>
        <source>Material / condition</source>
        <translation>Matériau / état</translation>
    </message>
    <message>
        <source>Tool marks</source>
        <translation>Traces d’outil</translation>
    </message>
    <message>
        <source>The layer the Annotation shading shows and the 3D lasso labels</source>
        <translation>La couche que montre l’ombrage Annotation et qu’étiquette le lasso 3D</translation>
    </message>
    <message>
        <source>Annotation layer</source>
        <translation>Couche d’annotation</translation>
    </message>
    <message>
        <source>How the points are lit: by a light at the eye (headlight), by the sky each cell sees (skydome; needs Tools › Compute skydome, else the headlight), in the scan&apos;s colours, by eye-dome lighting (the relief from the depth alone), or tinted by each cell&apos;s class in the annotation layer below</source>
        <translation>Comment les points sont éclairés : par une lumière à l’œil (phare), par le ciel que voit chaque cellule (skydome ; demande Outils › Calculer le skydome, sinon le phare), dans les couleurs du relevé, par éclairage eye-dome (le relief tiré de la seule profondeur), ou teintés par la classe de chaque cellule dans la couche d’annotation ci-dessous</translation>
    </message>
    <message>
        <source>Close the small gaps between the drawn points on screen, and hide a far surface seen through a narrow gap in a nearer one, when the view stops; openings of the scan wider than the points stay open</source>
        <translation>Combler à l’écran les petits vides entre les points dessinés, et cacher une surface lointaine vue par un vide étroit d’une surface plus proche, quand la vue s’arrête ; les ouvertures du relevé plus larges que les points restent ouvertes</translation>
    </message>
    <message>
        <source>Fill gaps</source>
        <translation>Combler les vides</translation>
    </message>
</context>
<context>
    <name>stylos::app::DockingActions</name>
    <message>
        <source>Docking against %1</source>
        <translation>Amarrage contre %1</translation>
    </message>
    <message>
        <source>The guides of this fragment are being fitted already, or its octree is not open yet</source>
        <translation>Les guides de ce fragment sont déjà en cours d’ajustement, ou son octree n’est pas encore ouvert</translation>
    </message>
    <message>
        <source>Guides of %1: %2 flutes, leading radius %3 mm, flute depth %4 mm, RMS %5 mm, %6 s</source>
        <translation>Guides de %1 : %2 cannelures, rayon directeur %3 mm, profondeur des cannelures %4 mm, RMS %5 mm, %6 s</translation>
    </message>
    <message>
        <source>&amp;Move tool</source>
        <translation>Outil &amp;Déplacer</translation>
    </message>
    <message>
        <source>Move the selected fragment with arrows and rings in the 3D view; Shift: finer, Ctrl: by degrees, Alt: tilts, L: the next frame, Escape: cancel the drag</source>
        <translation>Déplacer le fragment sélectionné avec des flèches et des anneaux dans la vue 3D ; Maj : plus fin, Ctrl : par degrés, Alt : inclinaisons, L : repère suivant, Échap : annuler le glisser</translation>
    </message>
    <message>
        <source>Gizmo &amp;frame</source>
        <translation>&amp;Repère du manipulateur</translation>
    </message>
    <message>
        <source>&amp;World</source>
        <translation>&amp;Monde</translation>
    </message>
    <message>
        <source>&amp;Fragment</source>
        <translation>&amp;Fragment</translation>
    </message>
    <message>
        <source>&amp;Drum</source>
        <translation>&amp;Tambour</translation>
    </message>
    <message>
        <source>Dock against this &amp;drum</source>
        <translation>Amarrer contre ce &amp;tambour</translation>
    </message>
    <message>
        <source>Use the axis and flutes of the selected fragment for the gizmo&apos;s Drum frame</source>
        <translation>Utiliser l’axe et les cannelures du fragment sélectionné pour le repère Tambour du manipulateur</translation>
    </message>
    <message>
        <source>Fit drum &amp;guides</source>
        <translation>Ajuster les &amp;guides du tambour</translation>
    </message>
    <message>
        <source>Fit the axis and the flute lines of the selected drum in the background</source>
        <translation>Ajuster en arrière-plan l’axe et les lignes de cannelure du tambour sélectionné</translation>
    </message>
    <message>
        <source>De&amp;lete guides</source>
        <translation>Supprimer &amp;les guides</translation>
    </message>
    <message>
        <source>Remove the axis and flute guides of the selected fragment</source>
        <translation>Retirer les guides d’axe et de cannelure du fragment sélectionné</translation>
    </message>
    <message>
        <source>Show &amp;guides</source>
        <translation>Afficher les &amp;guides</translation>
    </message>
    <message>
        <source>This fragment is being docked already, or its octree or the drum&apos;s is not open yet</source>
        <translation>Ce fragment est déjà en cours d’amarrage, ou son octree ou celui du tambour n’est pas encore ouvert</translation>
    </message>
    <message>
        <source>Dock to &amp;flutes</source>
        <translation>Amarrer aux &amp;cannelures</translation>
    </message>
    <message>
        <source>Snap the selected fragment onto the nearest flutes of the docking drum and refine its pose against them (one undo step)</source>
        <translation>Caler le fragment sélectionné sur les cannelures les plus proches du tambour d’amarrage et affiner sa pose contre elles (une seule étape d’annulation)</translation>
    </message>
    <message>
        <source>Docking &amp;locks</source>
        <translation>&amp;Verrous d’amarrage</translation>
    </message>
    <message>
        <source>Lock &amp;z (along the axis)</source>
        <translation>Verrouiller &amp;z (le long de l’axe)</translation>
    </message>
    <message>
        <source>Lock &amp;r (radial)</source>
        <translation>Verrouiller &amp;r (radial)</translation>
    </message>
    <message>
        <source>Lock &amp;θ (about the axis)</source>
        <translation>Verrouiller &amp;θ (autour de l’axe)</translation>
    </message>
    <message>
        <source>Lock &amp;tilts</source>
        <translation>Verrouiller les &amp;inclinaisons</translation>
    </message>
    <message>
        <source>Set &amp;axis from two points</source>
        <translation>Définir l’&amp;axe par deux points</translation>
    </message>
    <message>
        <source>Click two points on the selected fragment in the 3D view: its axis guide goes through them (Escape cancels)</source>
        <translation>Cliquez deux points sur le fragment sélectionné dans la vue 3D : son guide d’axe passe par eux (Échap annule)</translation>
    </message>
    <message>
        <source>&amp;Edit axis…</source>
        <translation>&amp;Modifier l’axe…</translation>
    </message>
    <message>
        <source>Type the point and direction of the selected fragment&apos;s axis guide</source>
        <translation>Saisir le point et la direction du guide d’axe du fragment sélectionné</translation>
    </message>
    <message>
        <source>&amp;Reverse axis</source>
        <translation>&amp;Inverser l’axe</translation>
    </message>
    <message>
        <source>Turn the selected fragment&apos;s axis guide end for end: a drum lying on its side whose développée came out upside down unrolls the right way up</source>
        <translation>Retourner bout pour bout le guide d’axe du fragment sélectionné : un tambour couché dont la développée est sortie à l’envers se déroule à l’endroit</translation>
    </message>
</context>
<context>
    <name>stylos::app::LegendDock</name>
    <message>
        <source>Legend</source>
        <translation>Légende</translation>
    </message>
</context>
<context>
    <name>stylos::app::LogDock</name>
    <message>
        <source>Log</source>
        <translation>Journal</translation>
    </message>
</context>
<context>
    <name>stylos::app::MainActions</name>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Aide</translation>
    </message>
    <message>
        <source>Open &amp;demo</source>
        <translation>Ouvrir la &amp;démonstration</translation>
    </message>
    <message>
        <source>&amp;About Stylos</source>
        <translation>À &amp;propos de Stylos</translation>
    </message>
    <message>
        <source>About Stylos</source>
        <translation>À propos de Stylos</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Stylos %1&lt;/h3&gt;&lt;p&gt;A workbench for very large 3D scans of monuments: column drums, capitals, fragments.&lt;/p&gt;&lt;p&gt;Point-based, after Duguet, Drettakis, Girardeau-Montaut, Martinez and Schneider (VAST 2004).&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Stylos %1&lt;/h3&gt;&lt;p&gt;Un atelier pour les très grands relevés 3D de monuments : tambours de colonne, chapiteaux, fragments.&lt;/p&gt;&lt;p&gt;Fondé sur les points, d’après Duguet, Drettakis, Girardeau-Montaut, Martinez et Schneider (VAST 2004).&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Édition</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>Affic&amp;hage</translation>
    </message>
    <message>
        <source>Standard &amp;views</source>
        <translation>&amp;Vues standard</translation>
    </message>
    <message>
        <source>&amp;Shading</source>
        <translation>O&amp;mbrage</translation>
    </message>
    <message>
        <source>&amp;Tools</source>
        <translation>&amp;Outils</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Langue</translation>
    </message>
    <message>
        <source>Undo the last change to the scene</source>
        <translation>Annuler la dernière modification de la scène</translation>
    </message>
    <message>
        <source>Redo the change undone last</source>
        <translation>Rétablir la dernière modification annulée</translation>
    </message>
    <message>
        <source>&amp;Remove from the scene</source>
        <translation>Re&amp;tirer de la scène</translation>
    </message>
    <message>
        <source>&amp;Fit to the scene</source>
        <translation>&amp;Cadrer la scène</translation>
    </message>
    <message>
        <source>Fit to the &amp;selection</source>
        <translation>Cadrer la &amp;sélection</translation>
    </message>
    <message>
        <source>Front</source>
        <translation>Avant</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Arrière</translation>
    </message>
    <message>
        <source>Left</source>
        <translation>Gauche</translation>
    </message>
    <message>
        <source>Right</source>
        <translation>Droite</translation>
    </message>
    <message>
        <source>Top</source>
        <translation>Dessus</translation>
    </message>
    <message>
        <source>Bottom</source>
        <translation>Dessous</translation>
    </message>
    <message>
        <source>Isometric</source>
        <translation>Isométrique</translation>
    </message>
    <message>
        <source>&amp;Orthographic</source>
        <translation>Projection &amp;orthographique</translation>
    </message>
    <message>
        <source>&amp;Headlight</source>
        <translation>Éclairage &amp;frontal</translation>
    </message>
    <message>
        <source>S&amp;kydome</source>
        <translation>S&amp;kydome</translation>
    </message>
    <message>
        <source>Scan &amp;colour</source>
        <translation>&amp;Couleur du relevé</translation>
    </message>
    <message>
        <source>Compute &amp;skydome</source>
        <translation>Calculer le &amp;skydome</translation>
    </message>
    <message>
        <source>Compute the 3D skydome (ambient occlusion) of the selected fragments in the background; the view then shades them by it</source>
        <translation>Calculer en arrière-plan le skydome 3D (occlusion ambiante) des fragments sélectionnés ; la vue les ombre ensuite d’après lui</translation>
    </message>
    <message>
        <source>&amp;Développée</source>
        <translation>&amp;Développée</translation>
    </message>
    <message>
        <source>Unroll the selected fragment in the Développée dock</source>
        <translation>Dérouler le fragment sélectionné dans le panneau Développée</translation>
    </message>
    <message>
        <source>Open the demo scene: a fluted drum, two of its fragments and an omphalos</source>
        <translation>Ouvrir la scène de démonstration : un tambour cannelé, deux de ses fragments et un omphalos</translation>
    </message>
    <message>
        <source>System language</source>
        <translation>Langue du système</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Annuler</translation>
    </message>
    <message>
        <source>&amp;Undo %1</source>
        <translation>&amp;Annuler : %1</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Rétablir</translation>
    </message>
    <message>
        <source>&amp;Redo %1</source>
        <translation>&amp;Rétablir : %1</translation>
    </message>
    <message>
        <source>&amp;Eye-dome lighting</source>
        <translation>&amp;Éclairage eye-dome (EDL)</translation>
    </message>
    <message>
        <source>&amp;Annotation</source>
        <translation>&amp;Annotation</translation>
    </message>
    <message>
        <source>Undo</source>
        <comment>toolbar</comment>
        <translation>Annuler</translation>
    </message>
    <message>
        <source>Redo</source>
        <comment>toolbar</comment>
        <translation>Rétablir</translation>
    </message>
    <message>
        <source>Fit</source>
        <comment>toolbar</comment>
        <translation>Cadrer</translation>
    </message>
    <message>
        <source>Orthographic</source>
        <comment>toolbar</comment>
        <translation>Orthographique</translation>
    </message>
    <message>
        <source>Skydome</source>
        <comment>toolbar</comment>
        <translation>Skydome</translation>
    </message>
    <message>
        <source>Développée</source>
        <comment>toolbar</comment>
        <translation>Développée</translation>
    </message>
</context>
<context>
    <name>stylos::app::MainWindow</name>
    <message>
        <source>Stylos</source>
        <translation>Stylos</translation>
    </message>
    <message>
        <source>%1 on %2</source>
        <translation>%1 sur %2</translation>
    </message>
    <message numerus="yes">
        <source>Remove %n fragment(s)</source>
        <translation>
            <numerusform>Retirer %n fragment</numerusform>
            <numerusform>Retirer %n fragments</numerusform>
        </translation>
    </message>
    <message>
        <source>Imported %1</source>
        <translation>Importé : %1</translation>
    </message>
    <message numerus="yes">
        <source>%n scan(s) could not be imported:</source>
        <translation>
            <numerusform>%n relevé n’a pas pu être importé :</numerusform>
            <numerusform>%n relevés n’ont pas pu être importés :</numerusform>
        </translation>
    </message>
    <message>
        <source>The skydome of the selection is being computed already, or its octrees are not open yet</source>
        <translation>Le skydome de la sélection est déjà en cours de calcul, ou ses octrees ne sont pas encore ouverts</translation>
    </message>
    <message>
        <source>%1[*] — Stylos</source>
        <translation>%1[*] — Stylos</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Fichier</translation>
    </message>
    <message>
        <source>Main toolbar</source>
        <translation>Barre d’outils principale</translation>
    </message>
    <message>
        <source>The 3D view needs OpenGL 3.3 (core profile), which this display does not offer.</source>
        <translation>La vue 3D nécessite OpenGL 3.3 (profil core), que cet affichage ne fournit pas.</translation>
    </message>
    <message>
        <source>Skydome of %1: %2 cells at level %3, %4 sky directions, %5 s</source>
        <translation>Skydome de %1 : %2 cellules au niveau %3, %4 directions du ciel, %5 s</translation>
    </message>
    <message>
        <source>View and tools toolbar</source>
        <translation>Barre de la vue et des outils</translation>
    </message>
    <message>
        <source>Could not compute the skydome of %1: its octree %2 does not exist</source>
        <translation>Impossible de calculer le skydome de %1 : son octree %2 n’existe pas</translation>
    </message>
</context>
<context>
    <name>stylos::app::PlateActions</name>
    <message>
        <source>Export &amp;plate…</source>
        <translation>Exporter une &amp;planche…</translation>
    </message>
    <message>
        <source>A publication plate at an exact scale: développées and orthographic views at 1:N with scale bars, legend and caption, as PDF, SVG, TIFF or PNG</source>
        <translation>Une planche de publication à échelle exacte : développées et vues orthographiques au 1:N avec échelles graphiques, légende et légende de figure, en PDF, SVG, TIFF ou PNG</translation>
    </message>
    <message>
        <source>Export &amp;développée image…</source>
        <translation>Exporter l’image de la &amp;développée…</translation>
    </message>
    <message>
        <source>The développée on show as PNG or TIFF with its pixel size, and its map (.json) beside it</source>
        <translation>La développée affichée en PNG ou TIFF avec sa taille de pixel, et sa correspondance (.json) à côté</translation>
    </message>
    <message>
        <source>Export plate</source>
        <translation>Exporter une planche</translation>
    </message>
    <message>
        <source>PDF (*.pdf);;SVG (*.svg);;TIFF (*.tif *.tiff);;PNG (*.png)</source>
        <translation>PDF (*.pdf);;SVG (*.svg);;TIFF (*.tif *.tiff);;PNG (*.png)</translation>
    </message>
    <message>
        <source>Drawing the plate %1</source>
        <translation>Dessin de la planche %1</translation>
    </message>
    <message>
        <source>Drawing the plate was cancelled</source>
        <translation>Le dessin de la planche a été annulé</translation>
    </message>
    <message>
        <source>Wrote the plate %1</source>
        <translation>Planche %1 écrite</translation>
    </message>
    <message>
        <source>Could not draw the plate: %1</source>
        <translation>Impossible de dessiner la planche : %1</translation>
    </message>
    <message>
        <source>There is no développée to export: compute one first (Tools › Développée)</source>
        <translation>Aucune développée à exporter : calculez-en une d’abord (Outils › Développée)</translation>
    </message>
    <message>
        <source>Export développée image</source>
        <translation>Exporter l’image de la développée</translation>
    </message>
    <message>
        <source>PNG (*.png);;TIFF (*.tif *.tiff)</source>
        <translation>PNG (*.png);;TIFF (*.tif *.tiff)</translation>
    </message>
    <message>
        <source>Could not export the développée: %1</source>
        <translation>Impossible d’exporter la développée : %1</translation>
    </message>
    <message>
        <source>Could not write the développée&apos;s map: %1</source>
        <translation>Impossible d’écrire la correspondance de la développée : %1</translation>
    </message>
    <message>
        <source>Wrote the développée %1 and its map</source>
        <translation>Développée %1 et sa correspondance écrites</translation>
    </message>
    <message>
        <source>Export &amp;view image…</source>
        <translation>Exporter l’image de la &amp;vue…</translation>
    </message>
    <message>
        <source>The visible fragments seen along the 3D view&apos;s direction, orthographic, every cell drawn, at a width you choose, as PNG or TIFF</source>
        <translation>Les fragments visibles vus selon la direction de la vue 3D, en orthographique, chaque cellule dessinée, à la largeur choisie, en PNG ou TIFF</translation>
    </message>
    <message>
        <source>Export view image</source>
        <translation>Exporter l’image de la vue</translation>
    </message>
    <message>
        <source>There is no 3D view to export</source>
        <translation>Il n’y a pas de vue 3D à exporter</translation>
    </message>
    <message>
        <source>Rendering the view %1</source>
        <translation>Rendu de la vue %1</translation>
    </message>
    <message>
        <source>Wrote the view image %1</source>
        <translation>Image de la vue %1 écrite</translation>
    </message>
    <message>
        <source>Width in pixels (the whole image at most %L1 million pixels)</source>
        <translation>Largeur en pixels (l’image entière au plus %L1 millions de pixels)</translation>
    </message>
    <message>
        <source>Rendering the view image %1 was cancelled</source>
        <translation>Le rendu de l’image de la vue %1 a été annulé</translation>
    </message>
    <message>
        <source>Could not render the view image %1: %2</source>
        <translation>Impossible de rendre l’image de la vue %1 : %2</translation>
    </message>
</context>
<context>
    <name>stylos::app::ProjectActions</name>
    <message>
        <source>&amp;New project</source>
        <translation>&amp;Nouveau projet</translation>
    </message>
    <message>
        <source>&amp;Open project…</source>
        <translation>&amp;Ouvrir un projet…</translation>
    </message>
    <message>
        <source>Open a Stylos project (.stylos)</source>
        <translation>Ouvrir un projet Stylos (.stylos)</translation>
    </message>
    <message>
        <source>Open &amp;recent</source>
        <translation>Ouvrir un projet &amp;récent</translation>
    </message>
    <message>
        <source>&amp;Save project</source>
        <translation>&amp;Enregistrer le projet</translation>
    </message>
    <message>
        <source>Save project &amp;as…</source>
        <translation>Enregistrer le projet &amp;sous…</translation>
    </message>
    <message>
        <source>&amp;Import scans…</source>
        <translation>&amp;Importer des relevés…</translation>
    </message>
    <message>
        <source>Build a packed octree of each scan in the background and add it to the scene</source>
        <translation>Construire en arrière-plan un octree compact de chaque relevé et l’ajouter à la scène</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Quitter</translation>
    </message>
    <message>
        <source>%1: a project opens alone, not with other files</source>
        <translation>%1 : un projet s’ouvre seul, pas avec d’autres fichiers</translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation>Projet ouvert : %1</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>Projet enregistré : %1</translation>
    </message>
    <message>
        <source>Save project</source>
        <translation>Enregistrer le projet</translation>
    </message>
    <message>
        <source>Stylos projects (*.stylos)</source>
        <translation>Projets Stylos (*.stylos)</translation>
    </message>
    <message>
        <source>Stylos</source>
        <translation>Stylos</translation>
    </message>
    <message>
        <source>The project %1 has unsaved changes.</source>
        <translation>Le projet %1 contient des modifications non enregistrées.</translation>
    </message>
    <message>
        <source>Open project</source>
        <translation>Ouvrir un projet</translation>
    </message>
    <message>
        <source>Import scans</source>
        <translation>Importer des relevés</translation>
    </message>
    <message>
        <source>No recent project</source>
        <translation>Aucun projet récent</translation>
    </message>
    <message>
        <source>Clear the list</source>
        <translation>Effacer la liste</translation>
    </message>
    <message numerus="yes">
        <source>The project uses %n octree(s) outside its folder, %1 in all.</source>
        <translation>
            <numerusform>Le projet utilise %n octree hors de son dossier, %1 en tout.</numerusform>
            <numerusform>Le projet utilise %n octrees hors de son dossier, %1 en tout.</numerusform>
        </translation>
    </message>
    <message>
        <source>Copied into the folder, they travel with it: the folder can be moved or copied whole. Left where they are, the project names them there.</source>
        <translation>Copiés dans le dossier, ils voyagent avec lui : le dossier peut être déplacé ou copié en entier. Laissés où ils sont, le projet les désigne à cet endroit.</translation>
    </message>
    <message>
        <source>Copy into the folder</source>
        <translation>Copier dans le dossier</translation>
    </message>
    <message>
        <source>Leave them where they are</source>
        <translation>Les laisser où ils sont</translation>
    </message>
    <message numerus="yes">
        <source>Saved %1, with %n octree(s) copied into its folder</source>
        <translation>
            <numerusform>%1 enregistré, %n octree copié dans son dossier</numerusform>
            <numerusform>%1 enregistré, %n octrees copiés dans son dossier</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Removed %n unused octree(s) from the cache, %1 freed</source>
        <translation>
            <numerusform>%n octree inutilisé retiré du cache, %1 libérés</numerusform>
            <numerusform>%n octrees inutilisés retirés du cache, %1 libérés</numerusform>
        </translation>
    </message>
    <message>
        <source>Open</source>
        <comment>toolbar</comment>
        <translation>Ouvrir</translation>
    </message>
    <message>
        <source>Save</source>
        <comment>toolbar</comment>
        <translation>Enregistrer</translation>
    </message>
    <message>
        <source>Import</source>
        <comment>toolbar</comment>
        <translation>Importer</translation>
    </message>
    <message>
        <source>The demo is rebuilt when it is opened again: save your work as a project of your own.</source>
        <translation>La démo est reconstruite à sa prochaine ouverture : enregistrez votre travail dans un projet à vous.</translation>
    </message>
    <message>
        <source>Could not save %1: it is in the demo&apos;s folder, rebuilt when the demo is opened again. Choose another folder.</source>
        <translation>Impossible d’enregistrer %1 : il est dans le dossier de la démo, reconstruit à sa prochaine ouverture. Choisissez un autre dossier.</translation>
    </message>
</context>
<context>
    <name>stylos::app::PropertiesDock</name>
    <message>
        <source>Properties</source>
        <translation>Propriétés</translation>
    </message>
    <message>
        <source>Fragment</source>
        <translation>Fragment</translation>
    </message>
    <message>
        <source>Display</source>
        <translation>Affichage</translation>
    </message>
    <message>
        <source>Contact with the drum</source>
        <translation>Contact avec le tambour</translation>
    </message>
    <message>
        <source>Placement in the drum frame</source>
        <translation>Placement dans le repère du tambour</translation>
    </message>
</context>
<context>
    <name>stylos::app::SceneDock</name>
    <message>
        <source>Scene</source>
        <translation>Scène</translation>
    </message>
</context>
<context>
    <name>stylos::app::StatusReadout</name>
    <message>
        <source>x %1  y %2  z %3 m</source>
        <translation>x %1  y %2  z %3 m</translation>
    </message>
    <message>
        <source>%1 fps · %2 ms · %3 M points</source>
        <translation>%1 fps · %2 ms · %3 M points</translation>
    </message>
</context>
<context>
    <name>stylos::app::TasksDock</name>
    <message>
        <source>Tasks</source>
        <translation>Tâches</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::AddFragmentCommand</name>
    <message>
        <source>Add %1</source>
        <translation>Ajouter %1</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::AssemblyDeveloppeeJob</name>
    <message>
        <source>Développée of %1</source>
        <translation>Développée de %1</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::AxisGuideEditor</name>
    <message>
        <source>Set axis cancelled</source>
        <translation>Définition de l’axe annulée</translation>
    </message>
    <message>
        <source>Click two points on %1 for its axis (Escape cancels)</source>
        <translation>Cliquez deux points sur %1 pour son axe (Échap annule)</translation>
    </message>
    <message>
        <source>The two points picked on %1 are the same: pick two points apart along its axis</source>
        <translation>Les deux points choisis sur %1 sont confondus : choisissez deux points écartés le long de son axe</translation>
    </message>
    <message>
        <source>Set the axis of %1 from two points</source>
        <translation>Définir l’axe de %1 par deux points</translation>
    </message>
    <message>
        <source>Axis of %1 set through the two points picked, %2 mm apart</source>
        <translation>Axe de %1 défini par les deux points choisis, distants de %2 mm</translation>
    </message>
    <message>
        <source>Edit the axis of %1</source>
        <translation>Modifier l’axe de %1</translation>
    </message>
    <message>
        <source>Reverse the axis of %1</source>
        <translation>Inverser l’axe de %1</translation>
    </message>
    <message>
        <source>The axis of %1 now points the other way: its développée turns upside down</source>
        <translation>L’axe de %1 pointe maintenant dans l’autre sens : sa développée se retourne</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::ClassMeasures</name>
    <message>
        <source>Areas of the classes of %1</source>
        <translation>Aires des classes de %1</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::ContactJob</name>
    <message>
        <source>Contact of %1 with the drum</source>
        <translation>Contact de %1 avec le tambour</translation>
    </message>
    <message>
        <source>Could not measure the contact of %1: %2.</source>
        <translation>Impossible de mesurer le contact de %1 : %2.</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::ContactReadoutWidget</name>
    <message>
        <source>Largest interpenetration:</source>
        <translation>Interpénétration maximale :</translation>
    </message>
    <message>
        <source>Median gap:</source>
        <translation>Écart médian :</translation>
    </message>
    <message>
        <source>Gap, 90 % of points:</source>
        <translation>Écart, 90 % des points :</translation>
    </message>
    <message>
        <source>Gap, 99 % of points:</source>
        <translation>Écart, 99 % des points :</translation>
    </message>
    <message>
        <source>Within 0.5 mm:</source>
        <translation>À moins de 0,5 mm :</translation>
    </message>
    <message>
        <source>Points measured:</source>
        <translation>Points mesurés :</translation>
    </message>
    <message>
        <source>Signed distance of the fragment&apos;s outer face to the drum&apos;s flute profile, along its normal; negative: inside the drum</source>
        <translation>Distance signée de la face extérieure du fragment au profil des cannelures du tambour, le long de sa normale ; négative : à l’intérieur du tambour</translation>
    </message>
    <message>
        <source>Set a docking drum with guides (Tools › Dock against this drum) and select another fragment.</source>
        <translation>Définissez un tambour d’amarrage avec des guides (Outils › Amarrer contre ce tambour) et sélectionnez un autre fragment.</translation>
    </message>
    <message>
        <source>Measuring…</source>
        <translation>Mesure en cours…</translation>
    </message>
    <message>
        <source>Against the docking drum&apos;s flute profile:</source>
        <translation>Contre le profil des cannelures du tambour d’amarrage :</translation>
    </message>
    <message>
        <source>The fragment does not touch the drum (no point of it within 5 mm of the profile).</source>
        <translation>Le fragment ne touche pas le tambour (aucun de ses points à moins de 5 mm du profil).</translation>
    </message>
    <message>
        <source>%1 mm</source>
        <translation>%1 mm</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <source>Against %1: %2</source>
        <translation>Contre %1 : %2</translation>
    </message>
    <message>
        <source>Against %1: no contact (no point within 5 mm)</source>
        <translation>Contre %1 : aucun contact (aucun point à moins de 5 mm)</translation>
    </message>
    <message>
        <source>Against %1: largest interpenetration %2, median gap %3, 90 % gap %4 (%5 points)</source>
        <translation>Contre %1 : interpénétration maximale %2, écart médian %3, écart à 90 % %4 (%5 points)</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::DemoScene</name>
    <message>
        <source>Could not create the demo folder %1.</source>
        <translation>Impossible de créer le dossier de démonstration %1.</translation>
    </message>
    <message>
        <source>Drum</source>
        <translation>Tambour</translation>
    </message>
    <message>
        <source>Fragment A</source>
        <translation>Fragment A</translation>
    </message>
    <message>
        <source>Fragment B</source>
        <translation>Fragment B</translation>
    </message>
    <message>
        <source>Omphalos</source>
        <translation>Omphalos</translation>
    </message>
    <message>
        <source>Axis</source>
        <translation>Axe</translation>
    </message>
    <message>
        <source>Preparing the demo scene</source>
        <translation>Préparation de la scène de démonstration</translation>
    </message>
    <message>
        <source>Could not prepare the demo scene: %1: %2.</source>
        <translation>Impossible de préparer la scène de démonstration : %1 : %2.</translation>
    </message>
    <message>
        <source>Flute</source>
        <translation>Cannelure</translation>
    </message>
    <message>
        <source>Drum 1 reconstruction</source>
        <translation>Reconstruction du tambour 1</translation>
    </message>
    <message>
        <source>Flute %1</source>
        <translation>Cannelure %1</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::DeveloppeeAnnotator</name>
    <message>
        <source>Erase %1</source>
        <translation>Effacer %1</translation>
    </message>
    <message>
        <source>Paint “%1”</source>
        <translation>Peindre « %1 »</translation>
    </message>
    <message>
        <source>Not painted: the développée of the assembly is out of date (%1). Compute it again to paint.</source>
        <translation>Rien n’est peint : la développée de l’assemblage n’est plus à jour (%1). Calculez-la à nouveau pour peindre.</translation>
    </message>
    <message>
        <source>its drum was removed</source>
        <translation>son tambour a été supprimé</translation>
    </message>
    <message>
        <source>a fragment was removed</source>
        <translation>un fragment a été supprimé</translation>
    </message>
    <message>
        <source>“%1” is no longer in the assembly</source>
        <translation>« %1 » n’est plus dans l’assemblage</translation>
    </message>
    <message>
        <source>“%1” was moved</source>
        <translation>« %1 » a été déplacé</translation>
    </message>
    <message>
        <source>the octree of “%1” changed</source>
        <translation>l’octree de « %1 » a changé</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::DeveloppeeJob</name>
    <message>
        <source>Développée of %1</source>
        <translation>Développée de %1</translation>
    </message>
    <message>
        <source>Could not compute the développée of %1: %2.</source>
        <translation>Impossible de calculer la développée de %1 : %2.</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::DeveloppeePanel</name>
    <message>
        <source>%1: %2, radius %3 mm, RMS %4 mm, %5 % inliers; %6 × %7 pixels of %8 mm; %9 s</source>
        <translation>%1 : %2, rayon %3 mm, RMS %4 mm, %5 % de points retenus ; %6 × %7 pixels de %8 mm ; %9 s</translation>
    </message>
    <message>
        <source>Surface</source>
        <translation>Surface</translation>
    </message>
    <message>
        <source>Shading</source>
        <translation>Ombrage</translation>
    </message>
    <message>
        <source>Pixel</source>
        <translation>Pixel</translation>
    </message>
    <message>
        <source>The surface the développée is unrolled from</source>
        <translation>La surface à partir de laquelle la développée est déroulée</translation>
    </message>
    <message>
        <source>How the heights become grey: the sky each point sees, one light, or height</source>
        <translation>Comment les hauteurs deviennent des niveaux de gris : le ciel vu par chaque point, une lumière unique, ou la hauteur</translation>
    </message>
    <message>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <source>Automatic</source>
        <translation>Automatique</translation>
    </message>
    <message>
        <source>Side of a pixel; Automatic uses the octree&apos;s leaf size</source>
        <translation>Côté d’un pixel ; Automatique utilise la taille des feuilles de l’octree</translation>
    </message>
    <message>
        <source>Use the axis guide</source>
        <translation>Utiliser le guide d’axe</translation>
    </message>
    <message>
        <source>Fit only the radius about the fragment&apos;s axis guide (needed for a fragment)</source>
        <translation>N’ajuster que le rayon autour du guide d’axe du fragment (nécessaire pour un fragment)</translation>
    </message>
    <message>
        <source>Fit</source>
        <translation>Cadrer</translation>
    </message>
    <message>
        <source>Fit the développée to the view (F)</source>
        <translation>Cadrer la développée dans la vue (F)</translation>
    </message>
    <message>
        <source>Compute</source>
        <translation>Calculer</translation>
    </message>
    <message>
        <source>Compute the développée of the selected fragment in the background</source>
        <translation>Calculer en arrière-plan la développée du fragment sélectionné</translation>
    </message>
    <message>
        <source>No développée yet: select a fragment and press Compute.</source>
        <translation>Pas encore de développée : sélectionnez un fragment et cliquez sur Calculer.</translation>
    </message>
    <message>
        <source>Computing the développée of %1…</source>
        <translation>Calcul de la développée de %1…</translation>
    </message>
    <message>
        <source>Select a fragment to compute its développée.</source>
        <translation>Sélectionnez un fragment pour calculer sa développée.</translation>
    </message>
    <message>
        <source>Press Compute for the développée of %1.</source>
        <translation>Cliquez sur Calculer pour obtenir la développée de %1.</translation>
    </message>
    <message>
        <source>Horizon directions</source>
        <translation>Directions d’horizon</translation>
    </message>
    <message>
        <source>Skydome shading of the développée: how many azimuths each pixel searches for its horizon (more is smoother and slower). Not the 3D view&apos;s skydome.</source>
        <translation>Ombrage skydome de la développée : le nombre d’azimuts où chaque pixel cherche son horizon (plus, c’est plus lisse et plus lent). Pas le skydome de la vue 3D.</translation>
    </message>
    <message>
        <source>noise %1 mm smoothed by %2 mm</source>
        <translation>bruit %1 mm lissé sur %2 mm</translation>
    </message>
    <message>
        <source>noise %1 mm, raw heights</source>
        <translation>bruit %1 mm, hauteurs brutes</translation>
    </message>
    <message>
        <source>Smooth noise</source>
        <translation>Lisser le bruit</translation>
    </message>
    <message>
        <source>Skydome: smooth the scanner&apos;s noise out of the heights before the horizon search, so that flat, open surfaces read evenly instead of as salt and pepper. Off: the raw heights.</source>
        <translation>Skydome : lisser le bruit du scanner dans les hauteurs avant la recherche de l’horizon, pour que les surfaces planes et dégagées se lisent uniformément au lieu de poivre et sel. Désactivé : les hauteurs brutes.</translation>
    </message>
    <message>
        <source>Width (Gaussian σ) of the smoothing; Automatic sets it from the noise measured on the heights. The status line says what was used.</source>
        <translation>Largeur (σ de la gaussienne) du lissage ; Automatique la fixe d’après le bruit mesuré sur les hauteurs. La ligne d’état indique la valeur utilisée.</translation>
    </message>
    <message>
        <source>; </source>
        <comment>between the parts of a status line</comment>
        <translation>&#x202f;; </translation>
    </message>
</context>
<context>
    <name>stylos::widgets::DeveloppeeSettings</name>
    <message>
        <source>the number of directions must be between %1 and %2</source>
        <translation>le nombre de directions doit être compris entre %1 et %2</translation>
    </message>
    <message>
        <source>the pixel size must be a positive length, or 0 for automatic</source>
        <translation>la taille de pixel doit être une longueur positive, ou 0 pour automatique</translation>
    </message>
    <message>
        <source>the light elevation must be between 0° and 90°</source>
        <translation>la hauteur angulaire de la lumière doit être comprise entre 0° et 90°</translation>
    </message>
    <message>
        <source>the axis needs a finite point and a non-zero direction</source>
        <translation>l’axe nécessite un point fini et une direction non nulle</translation>
    </message>
    <message>
        <source>Cylinder</source>
        <translation>Cylindre</translation>
    </message>
    <message>
        <source>Cone</source>
        <translation>Cône</translation>
    </message>
    <message>
        <source>Surface of revolution</source>
        <translation>Surface de révolution</translation>
    </message>
    <message>
        <source>Height</source>
        <translation>Hauteur</translation>
    </message>
    <message>
        <source>Light</source>
        <translation>Lumière</translation>
    </message>
    <message>
        <source>Skydome</source>
        <translation>Skydome</translation>
    </message>
    <message>
        <source>the unrolling radius must be a positive length</source>
        <translation>le rayon de déroulement doit être une longueur positive</translation>
    </message>
    <message>
        <source>the smoothing must be a positive length, or 0 for automatic</source>
        <translation>le lissage doit être une longueur positive, ou 0 pour automatique</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::DeveloppeeView</name>
    <message>
        <source>No développée yet: select a fragment and press Compute.</source>
        <translation>Pas encore de développée : sélectionnez un fragment et cliquez sur Calculer.</translation>
    </message>
    <message>
        <source>u %1 mm   v %2 mm   (no data)</source>
        <translation>u %1 mm   v %2 mm   (pas de données)</translation>
    </message>
    <message>
        <source>u %1 mm   v %2 mm   h %3 mm</source>
        <translation>u %1 mm   v %2 mm   h %3 mm</translation>
    </message>
    <message>
        <source>%1 m</source>
        <translation>%1 m</translation>
    </message>
    <message>
        <source>%1 mm</source>
        <translation>%1 mm</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::DockJob</name>
    <message>
        <source>Dock %1 to the flutes</source>
        <translation>Amarrer %1 aux cannelures</translation>
    </message>
    <message>
        <source>Could not dock %1: %2.</source>
        <translation>Impossible d’amarrer %1 : %2.</translation>
    </message>
    <message>
        <source>θ</source>
        <translation>θ</translation>
    </message>
    <message>
        <source>z</source>
        <translation>z</translation>
    </message>
    <message>
        <source>r</source>
        <translation>r</translation>
    </message>
    <message>
        <source>tangent</source>
        <translation>tangente</translation>
    </message>
    <message>
        <source>lean</source>
        <translation>dévers</translation>
    </message>
    <message>
        <source>roll</source>
        <translation>roulis</translation>
    </message>
    <message>
        <source>%1 ±%2°</source>
        <translation>%1 ±%2°</translation>
    </message>
    <message>
        <source>%1 ±%2 mm</source>
        <translation>%1 ±%2 mm</translation>
    </message>
    <message>
        <source>Docked %1: RMS %2 mm over %3 points, moved %4 flutes about the axis, %5 s</source>
        <translation>%1 amarré : RMS %2 mm sur %3 points, déplacé de %4 cannelures autour de l’axe, %5 s</translation>
    </message>
    <message>
        <source>uncertainty %1</source>
        <translation>incertitude %1</translation>
    </message>
    <message>
        <source>not fixed by the flutes, left as it was: %1</source>
        <translation>non fixé par les cannelures, laissé tel quel : %1</translation>
    </message>
    <message>
        <source>; </source>
        <comment>between the parts of a status line</comment>
        <translation>&#x202f;; </translation>
    </message>
    <message>
        <source>Could not dock %1: its %2 points are too few (at least 200 are needed).</source>
        <translation>Impossible d’amarrer %1 : ses %2 points sont trop peu nombreux (il en faut au moins 200).</translation>
    </message>
    <message>
        <source>Could not dock %1: it is too far from the drum; %2 of its points lie within %3 mm of the drum&apos;s surface (at least 200 are needed). Bring it nearer its place on the drum (the Move tool, or its placement in the drum frame in Properties) and dock again.</source>
        <translation>Impossible d’amarrer %1 : il est trop loin du tambour ; %2 de ses points sont à moins de %3 mm de la surface du tambour (il en faut au moins 200). Approchez-le de sa place sur le tambour (l’outil Déplacer, ou son placement dans le repère du tambour dans Propriétés) et amarrez-le de nouveau.</translation>
    </message>
    <message>
        <source>Could not dock %1: from where it stands its outer face does not meet the drum&apos;s surface. Bring it nearer its place on the drum and dock again.</source>
        <translation>Impossible d’amarrer %1 : depuis sa position, sa face extérieure ne rencontre pas la surface du tambour. Approchez-le de sa place sur le tambour et amarrez-le de nouveau.</translation>
    </message>
    <message>
        <source>Could not dock %1: no flutes can be read on its outer face (flute signal %2, at least %3 needed). Lock θ (Tools › Docking locks) to dock it against the drum&apos;s surface alone.</source>
        <translation>Impossible d’amarrer %1 : aucune cannelure ne se lit sur sa face extérieure (signal des cannelures %2, au moins %3 requis). Verrouillez θ (Outils › Verrous d’amarrage) pour l’amarrer contre la seule surface du tambour.</translation>
    </message>
    <message>
        <source>Could not dock %1: fewer than 200 of its points stayed on the flutes. Start it nearer its place and dock again.</source>
        <translation>Impossible d’amarrer %1 : moins de 200 de ses points sont restés sur les cannelures. Placez-le plus près de sa place et amarrez-le de nouveau.</translation>
    </message>
    <message>
        <source>Could not dock %1: the registration did not settle in %2 iterations.</source>
        <translation>Impossible d’amarrer %1 : le recalage ne s’est pas stabilisé en %2 itérations.</translation>
    </message>
    <message>
        <source>%1 times the drum&apos;s own RMS: it may rest on the wrong flute or be held off its place by a lock</source>
        <translation>%1 fois la RMS du tambour lui-même : il repose peut-être sur la mauvaise cannelure, ou un verrou l’empêche d’atteindre sa place</translation>
    </message>
    <message>
        <source>Could not dock %1: the registration did not settle in %2 iterations. θ is locked and may hold it off its flute: unlock θ (Tools › Docking locks), or bring it onto its flute first.</source>
        <translation>Impossible d’amarrer %1 : le recalage ne s’est pas stabilisé en %2 itérations. θ est verrouillé et peut le tenir à l’écart de sa cannelure : déverrouillez θ (Outils › Verrous d’amarrage) ou amenez-le d’abord sur sa cannelure.</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::DockRunner</name>
    <message>
        <source>The docking drum changed while its guides were fitted</source>
        <translation>Le tambour d’amarrage a changé pendant l’ajustement de ses guides</translation>
    </message>
    <message>
        <source>%1 or the drum moved while it was docked: the dock was not applied</source>
        <translation>%1 ou le tambour a bougé pendant l’amarrage : l’amarrage n’a pas été appliqué</translation>
    </message>
    <message>
        <source>Dock %1</source>
        <translation>Amarrer %1</translation>
    </message>
    <message>
        <source>Docking %1 was cancelled</source>
        <translation>L’amarrage de %1 a été annulé</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::DrumFramePoseWidget</name>
    <message>
        <source>θ about the axis:</source>
        <translation>θ autour de l’axe :</translation>
    </message>
    <message>
        <source>z along the axis:</source>
        <translation>z le long de l’axe :</translation>
    </message>
    <message>
        <source>r from the axis:</source>
        <translation>r depuis l’axe :</translation>
    </message>
    <message>
        <source>Lean:</source>
        <translation>Dévers :</translation>
    </message>
    <message>
        <source>Roll:</source>
        <translation>Roulis :</translation>
    </message>
    <message>
        <source>Azimuth of the fragment&apos;s centre about the drum axis, from the drum&apos;s reference direction (as in its développée); typing turns the fragment about the axis</source>
        <translation>Azimut du centre du fragment autour de l’axe du tambour, depuis la direction de référence du tambour (comme dans sa développée) ; une saisie tourne le fragment autour de l’axe</translation>
    </message>
    <message>
        <source>Height of the fragment&apos;s centre along the drum axis, from the axis guide&apos;s point</source>
        <translation>Hauteur du centre du fragment le long de l’axe du tambour, depuis le point du guide d’axe</translation>
    </message>
    <message>
        <source>Distance of the fragment&apos;s centre from the drum axis</source>
        <translation>Distance du centre du fragment à l’axe du tambour</translation>
    </message>
    <message>
        <source>Turn about the tangent through the fragment&apos;s centre (leans it in or out)</source>
        <translation>Rotation autour de la tangente par le centre du fragment (l’incline vers l’intérieur ou l’extérieur)</translation>
    </message>
    <message>
        <source>Turn about the radial direction through the fragment&apos;s centre (turns its flutes sideways)</source>
        <translation>Rotation autour de la direction radiale par le centre du fragment (tourne ses cannelures de côté)</translation>
    </message>
    <message>
        <source>This fragment has no drum with an axis guide (put it in an assembly with a drum, or Tools › Dock against this drum), or its octree is not open yet.</source>
        <translation>Ce fragment n’a pas de tambour avec un guide d’axe (placez-le dans un assemblage avec un tambour, ou Outils › Amarrer contre ce tambour), ou son octree n’est pas encore ouvert.</translation>
    </message>
    <message>
        <source>No fragment selected.</source>
        <translation>Aucun fragment sélectionné.</translation>
    </message>
    <message>
        <source>In the frame of %1:</source>
        <translation>Dans le repère de %1 :</translation>
    </message>
    <message>
        <source>Spin:</source>
        <translation>Rotation propre :</translation>
    </message>
    <message>
        <source>Turn about the line through the fragment&apos;s centre parallel to the axis; with θ and the tilts it fixes the orientation. The tilts and the spin are measured from the fragment&apos;s frame as scanned</source>
        <translation>Rotation autour de la droite passant par le centre du fragment, parallèle à l’axe ; avec θ et les inclinaisons, elle fixe l’orientation. Les inclinaisons et la rotation propre sont mesurées depuis le repère du fragment tel qu’il a été numérisé</translation>
    </message>
    <message>
        <source>This is the drum the others are placed against: select one of them.</source>
        <translation>C’est le tambour contre lequel les autres sont placés : sélectionnez l’un d’eux.</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::EditAxisDialog</name>
    <message>
        <source>Edit axis</source>
        <translation>Modifier l’axe</translation>
    </message>
    <message>
        <source>The axis guide in the fragment&apos;s own frame: a point on it and its direction.</source>
        <translation>Le guide d’axe dans le repère propre du fragment : un point de l’axe et sa direction.</translation>
    </message>
    <message>
        <source>Point (x, y, z):</source>
        <translation>Point (x, y, z) :</translation>
    </message>
    <message>
        <source>Direction (x, y, z):</source>
        <translation>Direction (x, y, z) :</translation>
    </message>
    <message>
        <source>The direction of the axis cannot be zero: give at least one non-zero component (for a vertical axis: 0, 0, 1).</source>
        <translation>La direction de l’axe ne peut pas être nulle : donnez au moins une composante non nulle (pour un axe vertical : 0, 0, 1).</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::ErrorText</name>
    <message>
        <source>Could not load %1: %2.</source>
        <translation>Impossible de charger %1 : %2.</translation>
    </message>
    <message>
        <source>the file does not exist</source>
        <translation>le fichier n’existe pas</translation>
    </message>
    <message>
        <source>the file cannot be read</source>
        <translation>le fichier ne peut pas être lu</translation>
    </message>
    <message>
        <source>the file format is not recognised</source>
        <translation>le format du fichier n’est pas reconnu</translation>
    </message>
    <message>
        <source>this format is not supported</source>
        <translation>ce format n’est pas pris en charge</translation>
    </message>
    <message>
        <source>the file is malformed</source>
        <translation>le fichier est mal formé</translation>
    </message>
    <message>
        <source>the file is truncated</source>
        <translation>le fichier est tronqué</translation>
    </message>
    <message>
        <source>the file is empty</source>
        <translation>le fichier est vide</translation>
    </message>
    <message>
        <source>the output could not be written</source>
        <translation>la sortie n’a pas pu être écrite</translation>
    </message>
    <message>
        <source>these data and settings do not allow it</source>
        <translation>ces données et ces réglages ne le permettent pas</translation>
    </message>
    <message>
        <source>not enough memory for this operation</source>
        <translation>mémoire insuffisante pour cette opération</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>annulé</translation>
    </message>
    <message>
        <source>unknown error</source>
        <translation>erreur inconnue</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::FragmentPropertiesWidget</name>
    <message>
        <source>Name</source>
        <translation>Nom</translation>
    </message>
    <message>
        <source>Visible</source>
        <translation>Visible</translation>
    </message>
    <message>
        <source>Colour</source>
        <translation>Couleur</translation>
    </message>
    <message>
        <source>X</source>
        <translation>X</translation>
    </message>
    <message>
        <source>Y</source>
        <translation>Y</translation>
    </message>
    <message>
        <source>Z</source>
        <translation>Z</translation>
    </message>
    <message>
        <source>Rotation X</source>
        <translation>Rotation X</translation>
    </message>
    <message>
        <source>Rotation Y</source>
        <translation>Rotation Y</translation>
    </message>
    <message>
        <source>Rotation Z</source>
        <translation>Rotation Z</translation>
    </message>
    <message>
        <source>Points</source>
        <translation>Points</translation>
    </message>
    <message>
        <source>Leaf cells</source>
        <translation>Cellules feuilles</translation>
    </message>
    <message>
        <source>Total cells</source>
        <translation>Cellules au total</translation>
    </message>
    <message>
        <source>Depth</source>
        <translation>Profondeur</translation>
    </message>
    <message>
        <source>File</source>
        <translation>Fichier</translation>
    </message>
    <message>
        <source>Shown in the 3D view</source>
        <translation>Affiché dans la vue 3D</translation>
    </message>
    <message>
        <source>Choose the fragment&apos;s display colour</source>
        <translation>Choisir la couleur d’affichage du fragment</translation>
    </message>
    <message>
        <source>Translation along the scene&apos;s x axis, in metres</source>
        <translation>Translation le long de l’axe x de la scène, en mètres</translation>
    </message>
    <message>
        <source>Rotation about the x axis, applied first, in degrees</source>
        <translation>Rotation autour de l’axe x, appliquée en premier, en degrés</translation>
    </message>
    <message>
        <source>missing</source>
        <translation>introuvable</translation>
    </message>
    <message>
        <source>opening…</source>
        <translation>ouverture…</translation>
    </message>
    <message>
        <source>Fragment colour</source>
        <translation>Couleur du fragment</translation>
    </message>
    <message>
        <source>Imported as</source>
        <translation>Importé en</translation>
    </message>
    <message>
        <source>%1 up, in %2</source>
        <translation>%1 vers le haut, en %2</translation>
    </message>
    <message>
        <source>offset %1, %2, %3</source>
        <translation>décalage %1, %2, %3</translation>
    </message>
    <message>
        <source>Size</source>
        <translation>Dimensions</translation>
    </message>
    <message>
        <source>Extent of the fragment&apos;s leaf cells along its own x, y and z axes (its scan&apos;s frame, z up), whatever its pose</source>
        <translation>Étendue des cellules feuilles du fragment le long de ses propres axes x, y et z (le repère de son relevé, z vers le haut), quelle que soit sa pose</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::GizmoReadout</name>
    <message>
        <source>Along the fragment&apos;s X: %1 mm</source>
        <translation>Selon le X du fragment : %1 mm</translation>
    </message>
    <message>
        <source>Along X: %1 mm</source>
        <translation>Selon X : %1 mm</translation>
    </message>
    <message>
        <source>Along the fragment&apos;s Y: %1 mm</source>
        <translation>Selon le Y du fragment : %1 mm</translation>
    </message>
    <message>
        <source>Along Y: %1 mm</source>
        <translation>Selon Y : %1 mm</translation>
    </message>
    <message>
        <source>Along the fragment&apos;s Z: %1 mm</source>
        <translation>Selon le Z du fragment : %1 mm</translation>
    </message>
    <message>
        <source>Along Z: %1 mm</source>
        <translation>Selon Z : %1 mm</translation>
    </message>
    <message>
        <source>About the fragment&apos;s X: %1°</source>
        <translation>Autour du X du fragment : %1°</translation>
    </message>
    <message>
        <source>About X: %1°</source>
        <translation>Autour de X : %1°</translation>
    </message>
    <message>
        <source>About the fragment&apos;s Y: %1°</source>
        <translation>Autour du Y du fragment : %1°</translation>
    </message>
    <message>
        <source>About Y: %1°</source>
        <translation>Autour de Y : %1°</translation>
    </message>
    <message>
        <source>About the fragment&apos;s Z: %1°</source>
        <translation>Autour du Z du fragment : %1°</translation>
    </message>
    <message>
        <source>About Z: %1°</source>
        <translation>Autour de Z : %1°</translation>
    </message>
    <message>
        <source>Along the drum axis: %1 mm</source>
        <translation>Le long de l’axe du tambour : %1 mm</translation>
    </message>
    <message>
        <source>Radially: %1 mm</source>
        <translation>Radialement : %1 mm</translation>
    </message>
    <message>
        <source>Tilt about the radial direction: %1°</source>
        <translation>Inclinaison autour de la direction radiale : %1°</translation>
    </message>
    <message>
        <source>Tilt about the tangent: %1°</source>
        <translation>Inclinaison autour de la tangente : %1°</translation>
    </message>
    <message numerus="yes">
        <source>About the drum axis: %1° (%n flute(s))</source>
        <translation>
            <numerusform>Autour de l’axe du tambour : %1° (%n cannelure)</numerusform>
            <numerusform>Autour de l’axe du tambour : %1° (%n cannelures)</numerusform>
        </translation>
    </message>
    <message>
        <source>About the drum axis: %1°</source>
        <translation>Autour de l’axe du tambour : %1°</translation>
    </message>
    <message>
        <source>%1 · Esc cancels</source>
        <translation>%1 · Échap annule</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::GuideFitJob</name>
    <message>
        <source>Drum guides of %1</source>
        <translation>Guides du tambour %1</translation>
    </message>
    <message>
        <source>Could not fit the guides of %1: %2.</source>
        <translation>Impossible d’ajuster les guides de %1 : %2.</translation>
    </message>
    <message>
        <source>Axis</source>
        <translation>Axe</translation>
    </message>
    <message>
        <source>Flute %1</source>
        <translation>Cannelure %1</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::GuideFitRunner</name>
    <message>
        <source>Delete the guides of %1</source>
        <translation>Supprimer les guides de %1</translation>
    </message>
    <message>
        <source>Fit the guides of %1</source>
        <translation>Ajuster les guides de %1</translation>
    </message>
    <message>
        <source>Fitting the guides of %1 was cancelled</source>
        <translation>L’ajustement des guides de %1 a été annulé</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::ImportOptionsDialog</name>
    <message>
        <source>Import options</source>
        <translation>Options d’importation</translation>
    </message>
    <message>
        <source>Stylos works with Z up and in metres. Say how the scans are stored: their points are turned and scaled once, as their octrees are built, and the project remembers it.</source>
        <translation>Stylos travaille avec Z vers le haut et en mètres. Indiquez comment les relevés sont enregistrés : leurs points sont tournés et mis à l’échelle une fois, à la construction de leurs octrees, et le projet s’en souvient.</translation>
    </message>
    <message>
        <source>&amp;Up axis of the scans:</source>
        <translation>&amp;Axe vertical des relevés :</translation>
    </message>
    <message>
        <source>&amp;Unit of the scans:</source>
        <translation>&amp;Unité des relevés :</translation>
    </message>
    <message>
        <source>+Z (already upright)</source>
        <translation>+Z (déjà debout)</translation>
    </message>
    <message>
        <source>−Z (upside down)</source>
        <translation>−Z (à l’envers)</translation>
    </message>
    <message>
        <source>+Y (Y up)</source>
        <translation>+Y (Y vers le haut)</translation>
    </message>
    <message>
        <source>−Y (Y down)</source>
        <translation>−Y (Y vers le bas)</translation>
    </message>
    <message>
        <source>+X (X up)</source>
        <translation>+X (X vers le haut)</translation>
    </message>
    <message>
        <source>−X (X down)</source>
        <translation>−X (X vers le bas)</translation>
    </message>
    <message>
        <source>metres (m)</source>
        <translation>mètres (m)</translation>
    </message>
    <message>
        <source>centimetres (cm)</source>
        <translation>centimètres (cm)</translation>
    </message>
    <message>
        <source>millimetres (mm)</source>
        <translation>millimètres (mm)</translation>
    </message>
    <message>
        <source>&amp;Offset (site coordinates, in that unit):</source>
        <translation>&amp;Décalage (coordonnées du site, dans cette unité) :</translation>
    </message>
    <message>
        <source>Subtracted from every x, before the turn and the scaling</source>
        <translation>Soustrait de chaque x, avant la rotation et la mise à l’échelle</translation>
    </message>
    <message>
        <source>Subtracted from every y, before the turn and the scaling</source>
        <translation>Soustrait de chaque y, avant la rotation et la mise à l’échelle</translation>
    </message>
    <message>
        <source>Subtracted from every z, before the turn and the scaling</source>
        <translation>Soustrait de chaque z, avant la rotation et la mise à l’échelle</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::LegendText</name>
    <message>
        <source>preserved marble</source>
        <translation>marbre conservé</translation>
    </message>
    <message>
        <source>fractured marble</source>
        <translation>marbre fracturé</translation>
    </message>
    <message>
        <source>plaster/restoration</source>
        <translation>plâtre/restauration</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>inconnu</translation>
    </message>
    <message>
        <source>point</source>
        <translation>pointe</translation>
    </message>
    <message>
        <source>flat chisel</source>
        <translation>ciseau plat</translation>
    </message>
    <message>
        <source>claw chisel</source>
        <translation>gradine</translation>
    </message>
    <message>
        <source>drill</source>
        <translation>trépan</translation>
    </message>
    <message>
        <source>rasp</source>
        <translation>râpe</translation>
    </message>
    <message>
        <source>Material / condition</source>
        <translation>Matériau / état</translation>
    </message>
    <message>
        <source>Tool marks</source>
        <translation>Traces d’outil</translation>
    </message>
    <message>
        <source>None</source>
        <translation>Aucune</translation>
    </message>
    <message>
        <source>Diagonal</source>
        <translation>Diagonale</translation>
    </message>
    <message>
        <source>Back diagonal</source>
        <translation>Diagonale inverse</translation>
    </message>
    <message>
        <source>Cross</source>
        <translation>Quadrillage</translation>
    </message>
    <message>
        <source>Diagonal cross</source>
        <translation>Quadrillage diagonal</translation>
    </message>
    <message>
        <source>Dots</source>
        <translation>Points</translation>
    </message>
    <message>
        <source>Horizontal</source>
        <translation>Horizontale</translation>
    </message>
    <message>
        <source>Vertical</source>
        <translation>Verticale</translation>
    </message>
    <message>
        <source>Solid</source>
        <translation>Plein</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::LegendWidget</name>
    <message>
        <source>Colour of “%1”</source>
        <translation>Couleur de « %1 »</translation>
    </message>
    <message>
        <source>Rename class “%1” to “%2”</source>
        <translation>Renommer la classe « %1 » en « %2 »</translation>
    </message>
    <message>
        <source>Recolour class “%1”</source>
        <translation>Changer la couleur de la classe « %1 »</translation>
    </message>
    <message>
        <source>Change the hatch of “%1”</source>
        <translation>Changer la hachure de « %1 »</translation>
    </message>
    <message>
        <source>class %1</source>
        <translation>classe %1</translation>
    </message>
    <message>
        <source>Add class “%1”</source>
        <translation>Ajouter la classe « %1 »</translation>
    </message>
    <message>
        <source>Delete class “%1”</source>
        <translation>Supprimer la classe « %1 »</translation>
    </message>
    <message numerus="yes">
        <source>%n cell(s) hold this class. What becomes of them?</source>
        <translation>
            <numerusform>%Ln cellule porte cette classe. Que devient-elle ?</numerusform>
            <numerusform>%Ln cellules portent cette classe. Que deviennent-elles ?</numerusform>
        </translation>
    </message>
    <message>
        <source>Unlabel them</source>
        <translation>Les désannoter</translation>
    </message>
    <message>
        <source>Move them to</source>
        <translation>Les passer dans</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Supprimer</translation>
    </message>
    <message>
        <source>The black-and-white pattern of this class on plates</source>
        <translation>Le motif noir et blanc de cette classe sur les planches</translation>
    </message>
    <message>
        <source>Being measured…</source>
        <translation>Mesure en cours…</translation>
    </message>
    <message>
        <source>Surface area on the object, m²</source>
        <translation>Aire de la surface sur l’objet, m²</translation>
    </message>
    <message>
        <source>Class</source>
        <translation>Classe</translation>
    </message>
    <message>
        <source>Hatch</source>
        <translation>Hachure</translation>
    </message>
    <message>
        <source>Cells</source>
        <translation>Cellules</translation>
    </message>
    <message>
        <source>Area (m²)</source>
        <translation>Aire (m²)</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Ajouter</translation>
    </message>
    <message>
        <source>Add a class to the layer of the selected row</source>
        <translation>Ajouter une classe à la couche de la ligne sélectionnée</translation>
    </message>
    <message>
        <source>Colour…</source>
        <translation>Couleur…</translation>
    </message>
    <message>
        <source>Change the colour of the selected class</source>
        <translation>Changer la couleur de la classe sélectionnée</translation>
    </message>
    <message>
        <source>Delete…</source>
        <translation>Supprimer…</translation>
    </message>
    <message>
        <source>Delete the selected class (its cells are unlabelled or moved to another class)</source>
        <translation>Supprimer la classe sélectionnée (ses cellules sont désannotées ou passées dans une autre classe)</translation>
    </message>
    <message>
        <source>Click a class to paint it; double-click its name to rename it</source>
        <translation>Cliquer une classe pour la peindre ; double-cliquer son nom pour la renommer</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::PaintToolBar</name>
    <message>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <source> %</source>
        <translation> %</translation>
    </message>
    <message>
        <source>Pan</source>
        <translation>Déplacer</translation>
    </message>
    <message>
        <source>Navigate: drag to pan, click to mark the point in 3D (N)</source>
        <translation>Naviguer : glisser pour déplacer la vue, cliquer pour marquer le point en 3D (N)</translation>
    </message>
    <message>
        <source>Brush</source>
        <translation>Pinceau</translation>
    </message>
    <message>
        <source>Paint the active class with a round brush (B)</source>
        <translation>Peindre la classe active avec un pinceau rond (B)</translation>
    </message>
    <message>
        <source>Eraser</source>
        <translation>Gomme</translation>
    </message>
    <message>
        <source>Unlabel the cells under a round brush (E)</source>
        <translation>Désannoter les cellules sous un pinceau rond (E)</translation>
    </message>
    <message>
        <source>Polygon</source>
        <translation>Polygone</translation>
    </message>
    <message>
        <source>Fill a polygon with the active class: click its corners and double-click, or drag a lasso (L); Escape cancels</source>
        <translation>Remplir un polygone avec la classe active : cliquer ses sommets puis double-cliquer, ou tracer un lasso (L) ; Échap annule</translation>
    </message>
    <message>
        <source>Wand</source>
        <translation>Baguette</translation>
    </message>
    <message>
        <source>Fill the connected pixels of similar height or shading with the active class (W)</source>
        <translation>Remplir avec la classe active les pixels connexes de hauteur ou d’ombrage voisins (W)</translation>
    </message>
    <message>
        <source>Holes</source>
        <translation>Trous</translation>
    </message>
    <message>
        <source>Fill the holes enclosed by the clicked region with its class (H)</source>
        <translation>Remplir avec sa classe les trous que la région cliquée entoure (H)</translation>
    </message>
    <message>
        <source>The annotation layer shown and painted</source>
        <translation>La couche d’annotation affichée et peinte</translation>
    </message>
    <message>
        <source>The class the brush, polygon and wand paint</source>
        <translation>La classe que peignent le pinceau, le polygone et la baguette</translation>
    </message>
    <message>
        <source>Size</source>
        <translation>Taille</translation>
    </message>
    <message>
        <source>Brush and eraser diameter on the object</source>
        <translation>Diamètre du pinceau et de la gomme sur l’objet</translation>
    </message>
    <message>
        <source>Height</source>
        <translation>Hauteur</translation>
    </message>
    <message>
        <source>Shading</source>
        <translation>Ombrage</translation>
    </message>
    <message>
        <source>What the magic wand compares</source>
        <translation>Ce que compare la baguette magique</translation>
    </message>
    <message>
        <source>The magic wand takes pixels within this of the clicked one</source>
        <translation>La baguette magique prend les pixels à moins de cet écart de celui cliqué</translation>
    </message>
    <message>
        <source>Overlay</source>
        <translation>Calque</translation>
    </message>
    <message>
        <source>Opacity of the annotation over the développée</source>
        <translation>Opacité de l’annotation sur la développée</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::PlateDialog</name>
    <message>
        <source>Développée</source>
        <translation>Développée</translation>
    </message>
    <message>
        <source>Front</source>
        <translation>Face</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Arrière</translation>
    </message>
    <message>
        <source>Left</source>
        <translation>Gauche</translation>
    </message>
    <message>
        <source>Right</source>
        <translation>Droite</translation>
    </message>
    <message>
        <source>Top</source>
        <translation>Dessus</translation>
    </message>
    <message>
        <source>Bottom</source>
        <translation>Dessous</translation>
    </message>
    <message>
        <source>Current view</source>
        <translation>Vue actuelle</translation>
    </message>
    <message>
        <source>Skydome</source>
        <translation>Skydome</translation>
    </message>
    <message>
        <source>Light</source>
        <translation>Lumière</translation>
    </message>
    <message>
        <source>Height</source>
        <translation>Hauteur</translation>
    </message>
    <message>
        <source>Headlight</source>
        <translation>Éclairage frontal</translation>
    </message>
    <message>
        <source>Page</source>
        <translation>Page</translation>
    </message>
    <message>
        <source>Margins</source>
        <translation>Marges</translation>
    </message>
    <message>
        <source>Resolution (dpi)</source>
        <translation>Résolution (ppp)</translation>
    </message>
    <message>
        <source>Bits per sample (TIFF, PNG)</source>
        <translation>Bits par échantillon (TIFF, PNG)</translation>
    </message>
    <message>
        <source>Template</source>
        <translation>Modèle</translation>
    </message>
    <message>
        <source>Caption</source>
        <translation>Légende de figure</translation>
    </message>
    <message>
        <source>Add panel</source>
        <translation>Ajouter un panneau</translation>
    </message>
    <message>
        <source>Remove panel</source>
        <translation>Retirer le panneau</translation>
    </message>
    <message>
        <source>Panels</source>
        <translation>Panneaux</translation>
    </message>
    <message>
        <source>Export plate</source>
        <translation>Exporter une planche</translation>
    </message>
    <message>
        <source>Landscape</source>
        <translation>Paysage</translation>
    </message>
    <message>
        <source>Legend of the annotation classes</source>
        <translation>Légende des classes d’annotation</translation>
    </message>
    <message>
        <source>Export…</source>
        <translation>Exporter…</translation>
    </message>
    <message>
        <source>View</source>
        <translation>Vue</translation>
    </message>
    <message>
        <source>Scale 1:</source>
        <translation>Échelle 1:</translation>
    </message>
    <message>
        <source>Shading</source>
        <translation>Ombrage</translation>
    </message>
    <message>
        <source>Annotation</source>
        <translation>Annotation</translation>
    </message>
    <message>
        <source>Hatches</source>
        <translation>Hachures</translation>
    </message>
    <message>
        <source>Fragment</source>
        <translation>Fragment</translation>
    </message>
    <message>
        <source>Choose a template…</source>
        <translation>Choisir un modèle…</translation>
    </message>
    <message>
        <source>Développée and front view</source>
        <translation>Développée et vue de face</translation>
    </message>
    <message>
        <source>Front, right and top views</source>
        <translation>Vues de face, de droite et de dessus</translation>
    </message>
    <message>
        <source>None</source>
        <translation>Aucune</translation>
    </message>
    <message>
        <source>Material / condition</source>
        <translation>Matériau / état</translation>
    </message>
    <message>
        <source>Tool marks</source>
        <translation>Traces d’outil</translation>
    </message>
    <message>
        <source>(all visible; the first for a développée)</source>
        <translation>(tous les visibles ; le premier pour une développée)</translation>
    </message>
    <message>
        <source>Drawing the preview…</source>
        <translation>Dessin de l’aperçu…</translation>
    </message>
    <message>
        <source>Turned (%1 × %2 mm)</source>
        <translation>Tournée (%1 × %2 mm)</translation>
    </message>
    <message>
        <source>A4 (210 × 297 mm)</source>
        <translation>A4 (210 × 297 mm)</translation>
    </message>
    <message>
        <source>A3 (297 × 420 mm)</source>
        <translation>A3 (297 × 420 mm)</translation>
    </message>
    <message>
        <source>US letter (215.9 × 279.4 mm)</source>
        <translation>Lettre US (215,9 × 279,4 mm)</translation>
    </message>
    <message>
        <source>Journal print area, 170 × 105 mm</source>
        <translation>Zone d’impression de revue, 170 × 105 mm</translation>
    </message>
    <message>
        <source>Journal print area, 205 × 135 mm</source>
        <translation>Zone d’impression de revue, 205 × 135 mm</translation>
    </message>
    <message>
        <source>%1 × %2 mm</source>
        <translation>%1 × %2 mm</translation>
    </message>
    <message>
        <source>Panel %1 (%2)</source>
        <translation>Le panneau %1 (%2)</translation>
    </message>
    <message>
        <source>The panel (%1)</source>
        <translation>Le panneau (%1)</translation>
    </message>
    <message>
        <source>%1 is %2; the print area is %3: use %4 or smaller, or a larger page.</source>
        <translation>%1 mesure %2 ; la zone d’impression mesure %3 : choisissez %4 ou une échelle plus petite, ou une page plus grande.</translation>
    </message>
    <message>
        <source>%1 is %2; the print area is %3: no scale fits this page, use a larger page.</source>
        <translation>%1 mesure %2 ; la zone d’impression mesure %3 : aucune échelle ne tient sur cette page, choisissez une page plus grande.</translation>
    </message>
    <message>
        <source>%1, placed at (%2, %3) mm, is %4 with its texts and leaves the %5 page.</source>
        <translation>%1, placé en (%2 ; %3) mm, mesure %4 avec ses textes et sort de la page de %5.</translation>
    </message>
    <message>
        <source>The plate needs %1 mm of height; the print area is %2: use smaller scales, a larger page or the other orientation.</source>
        <translation>La planche demande %1 mm de hauteur ; la zone d’impression mesure %2 : choisissez des échelles plus petites, une page plus grande ou l’autre orientation.</translation>
    </message>
    <message>
        <source>The plate needs %1 mm of height; the print area is %2: use smaller scales (%3), a larger page or the other orientation.</source>
        <translation>La planche demande %1 mm de hauteur ; la zone d’impression mesure %2 : choisissez des échelles plus petites (%3), une page plus grande ou l’autre orientation.</translation>
    </message>
    <message>
        <source>The caption needs %1 mm of height on its own; the print area is %2: shorten the caption or use a larger page.</source>
        <translation>La légende de figure demande à elle seule %1 mm de hauteur ; la zone d’impression mesure %2 : raccourcissez-la ou choisissez une page plus grande.</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::PlateTexts</name>
    <message>
        <source>développée</source>
        <translation>développée</translation>
    </message>
    <message>
        <source>front view</source>
        <translation>vue de face</translation>
    </message>
    <message>
        <source>back view</source>
        <translation>vue arrière</translation>
    </message>
    <message>
        <source>left view</source>
        <translation>vue de gauche</translation>
    </message>
    <message>
        <source>right view</source>
        <translation>vue de droite</translation>
    </message>
    <message>
        <source>top view</source>
        <translation>vue de dessus</translation>
    </message>
    <message>
        <source>bottom view</source>
        <translation>vue de dessous</translation>
    </message>
    <message>
        <source>orthographic view</source>
        <translation>vue orthographique</translation>
    </message>
    <message>
        <source>skydome</source>
        <translation>skydome</translation>
    </message>
    <message>
        <source>light</source>
        <translation>lumière</translation>
    </message>
    <message>
        <source>height</source>
        <translation>hauteur</translation>
    </message>
    <message>
        <source>headlight</source>
        <translation>éclairage frontal</translation>
    </message>
    <message>
        <source>axis</source>
        <translation>axe</translation>
    </message>
    <message>
        <source>.</source>
        <comment>the decimal point of the numbers on a plate</comment>
        <translation>,</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::RemoveFragmentCommand</name>
    <message>
        <source>Remove %1</source>
        <translation>Retirer %1</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::RenameFragmentCommand</name>
    <message>
        <source>Rename %1 to %2</source>
        <translation>Renommer %1 en %2</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::ScanImporter</name>
    <message>
        <source>Scans and octrees (%1)</source>
        <translation>Relevés et octrees (%1)</translation>
    </message>
    <message>
        <source>Packed octrees (*.poct)</source>
        <translation>Octrees compacts (*.poct)</translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation>Tous les fichiers (*)</translation>
    </message>
    <message>
        <source>Importing %1</source>
        <translation>Importation de %1</translation>
    </message>
    <message>
        <source>Could not import %1: %2.</source>
        <translation>Impossible d’importer %1 : %2.</translation>
    </message>
    <message>
        <source>Import %1</source>
        <translation>Importer %1</translation>
    </message>
    <message numerus="yes">
        <source>%1: %Ln point(s) with NaN or infinite coordinates skipped</source>
        <translation>
            <numerusform>%1 : %Ln point aux coordonnées NaN ou infinies ignoré</numerusform>
            <numerusform>%1 : %Ln points aux coordonnées NaN ou infinies ignorés</numerusform>
        </translation>
    </message>
    <message>
        <source>Could not import %1: the folder %2 cannot be created or written to.</source>
        <translation>Impossible d’importer %1 : le dossier %2 ne peut pas être créé ou n’accepte pas d’écriture.</translation>
    </message>
    <message numerus="yes">
        <source>%1 holds %Ln scan(s), merged into one fragment; each point&apos;s normal was estimated from its own scan&apos;s points</source>
        <translation>
            <numerusform>%1 contient %Ln relevé, fusionné en un seul fragment ; la normale de chaque point a été estimée à partir des points de son propre relevé</numerusform>
            <numerusform>%1 contient %Ln relevés, fusionnés en un seul fragment ; la normale de chaque point a été estimée à partir des points de son propre relevé</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>stylos::widgets::SceneDocument</name>
    <message>
        <source>Untitled</source>
        <translation>Sans titre</translation>
    </message>
    <message>
        <source>The project has no file yet: choose one with Save as.</source>
        <translation>Le projet n’a pas encore de fichier : choisissez-en un avec Enregistrer sous.</translation>
    </message>
    <message>
        <source>Could not save %1: %2.</source>
        <translation>Impossible d’enregistrer %1 : %2.</translation>
    </message>
    <message>
        <source>Opening %1</source>
        <translation>Ouverture de %1</translation>
    </message>
    <message>
        <source>New assembly %1</source>
        <translation>Nouvel assemblage %1</translation>
    </message>
    <message>
        <source>Remove assembly %1</source>
        <translation>Dissoudre l’assemblage %1</translation>
    </message>
    <message>
        <source>Rename %1</source>
        <translation>Renommer %1</translation>
    </message>
    <message>
        <source>Take out of assembly</source>
        <translation>Sortir de l’assemblage</translation>
    </message>
    <message>
        <source>Move into %1</source>
        <translation>Placer dans %1</translation>
    </message>
    <message>
        <source>Move %1</source>
        <translation>Déplacer %1</translation>
    </message>
    <message>
        <source>Set the drum of %1</source>
        <translation>Choisir le tambour de %1</translation>
    </message>
    <message>
        <source>Show %1</source>
        <translation>Afficher %1</translation>
    </message>
    <message>
        <source>Hide %1</source>
        <translation>Masquer %1</translation>
    </message>
    <message>
        <source>Change the legend</source>
        <translation>Modifier la légende</translation>
    </message>
    <message>
        <source>Remove the class %1</source>
        <translation>Supprimer la classe %1</translation>
    </message>
    <message>
        <source>Could not save the annotations of %1 into %2: %3.</source>
        <translation>Impossible d’enregistrer les annotations de %1 dans %2 : %3.</translation>
    </message>
    <message>
        <source>Keep the plate&apos;s settings</source>
        <translation>Conserver les réglages de la planche</translation>
    </message>
    <message>
        <source>Could not copy the octrees into the project&apos;s folder: %1.</source>
        <translation>Impossible de copier les octrees dans le dossier du projet : %1.</translation>
    </message>
    <message>
        <source>The plate layout kept in %1 could not be read: the project opens without it, and its text stays in the file until a new plate is set (File › Export plate…).</source>
        <translation>La mise en planche conservée dans %1 n’a pas pu être lue : le projet s’ouvre sans elle, et son texte reste dans le fichier jusqu’à ce qu’une nouvelle planche soit définie (Fichier › Exporter une planche…).</translation>
    </message>
    <message>
        <source>%1 holds keys this version of Stylos does not read; they are left out and will not be saved: %2</source>
        <translation>%1 contient des clés que cette version de Stylos ne lit pas ; elles sont ignorées et ne seront pas enregistrées : %2</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::SceneTreeModel</name>
    <message>
        <source>%1 (missing)</source>
        <translation>%1 (introuvable)</translation>
    </message>
    <message>
        <source>Axis</source>
        <translation>Axe</translation>
    </message>
    <message>
        <source>Groove</source>
        <translation>Cannelure</translation>
    </message>
    <message>
        <source>Scene</source>
        <translation>Scène</translation>
    </message>
    <message>
        <source>Développée (%1, %2 × %3)</source>
        <translation>Développée (%1, %2 × %3)</translation>
    </message>
    <message numerus="yes">
        <source>Assembly of %n fragment(s)</source>
        <translation>
            <numerusform>Assemblage de %n fragment</numerusform>
            <numerusform>Assemblage de %n fragments</numerusform>
        </translation>
    </message>
    <message>
        <source>Docks against %1</source>
        <translation>S’amarre contre %1</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::SetFragmentColourCommand</name>
    <message>
        <source>Change the colour of %1</source>
        <translation>Changer la couleur de %1</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::SetFragmentGuidesCommand</name>
    <message>
        <source>Change the guides of %1</source>
        <translation>Modifier les guides de %1</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::SetFragmentPoseCommand</name>
    <message>
        <source>Move %1</source>
        <translation>Déplacer %1</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::SetFragmentVisibleCommand</name>
    <message>
        <source>Show %1</source>
        <translation>Afficher %1</translation>
    </message>
    <message>
        <source>Hide %1</source>
        <translation>Masquer %1</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::SkydomeJob</name>
    <message>
        <source>Skydome of %1</source>
        <translation>Skydome de %1</translation>
    </message>
    <message>
        <source>Could not compute the skydome of %1: %2.</source>
        <translation>Impossible de calculer le skydome de %1 : %2.</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::TaskListWidget</name>
    <message>
        <source>No background tasks</source>
        <translation>Aucune tâche en arrière-plan</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Annuler</translation>
    </message>
    <message>
        <source>Stop this task</source>
        <translation>Arrêter cette tâche</translation>
    </message>
    <message>
        <source>Waiting…</source>
        <translation>En attente…</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::ViewportWidget</name>
    <message>
        <source>The 3D view needs OpenGL 3.3: %1</source>
        <translation>La vue 3D nécessite OpenGL 3.3 : %1</translation>
    </message>
</context>
</TS>
