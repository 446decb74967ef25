#!/usr/bin/perl -0777 -n
# The shell-script scanner of scripts/check_deps.sh (a file of its own, so that the scan of the
# shell scripts never reads this program's quotes and backticks as shell code). Prints
# "FILE: WORD" for the first word of every pipeline segment of the script it reads whole, after
# VAR=value assignments; $(...) and backquoted contents become segments of their own before
# quoted strings are dropped. Run as: perl -0777 -n scripts/scan_commands.pl FILE
s/^[ \t]*#.*$//mg;                                  # comment lines
my @seg;
while (s/\$\(([^()]*)\)/ Q /) { push @seg, $1 }       # $(...) become segments of their own
while (s/`([^`]*)`/ Q /) { push @seg, $1 }
push @seg, $_;
for my $t (@seg) {
  # Quoted strings (even multi-line), in one left-to-right pass: an apostrophe inside a
  # double-quoted string opens nothing (two passes, single quotes first, paired the
  # apostrophes of two messages and exposed the words between them as commands).
  $t =~ s/"(?:[^"\\]|\\.)*"|\x27[^\x27]*\x27/Q/gs;
  $t =~ s/[ \t]#.*$//mg;                              # trailing comments
  $t =~ s/=\([^()]*\)/=Q/g;                            # array assignments a=(...)
  $t =~ s/(^[ \t]*|\bin[ \t]+|;;[ \t]*)[^\s()|;]+(?:\|[^\s()|;]+)*\)/$1/mg;  # case arms a|b)
  for my $part (split /&&|\|\||[|;(){}\n]/, $t) {
    my @w = split " ", $part;
    shift @w while @w && ($w[0] =~ /^[A-Za-z_][A-Za-z0-9_]*=/ ||
                          $w[0] =~ /^(then|do|else|elif|if|while|until|time|exec|!)$/);
    print "$ARGV: $w[0]\n" if @w;
  }
}
